#pragma once
// How a verifier tells pt-grade that its worker, not a test, ended the run
// (README.md beside this file): its exit status, set by verifier_link.cpp and
// read by grade_part.cpp. The test that was running gets no verdict, and
// pt-grade charges it with the worker's end and starts both again on the
// tests left.
namespace pt::boundary {

// The worker died or closed the link.
constexpr int kWorkerLost = 87;
// The worker never reached its main (a static initializer): it would do the
// same for every test, so pt-grade charges them all at once.
constexpr int kWorkerNeverStarted = 88;
// The worker wrote what no honest worker writes on the link.
constexpr int kWorkerBrokeLink = 89;

}  // namespace pt::boundary
