// `pt-grade submission` in a build without the sandbox (PT_SANDBOX off: the
// grading kit's build and runs are confined with Linux's interfaces, which
// compile/ and sandbox/ use): grade.cpp refuses it before it gets here.
#include "submission/submission.h"

#include <cstdio>

namespace pt::grade {

int grade_submission(const SubmissionOptions&) {
  std::fprintf(stderr, "pt-grade submission: %s\n", sandbox_unavailable().c_str());
  return 2;
}

}  // namespace pt::grade
