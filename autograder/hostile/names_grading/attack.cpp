// Not an attack: names that only look like one. The task file is the
// solution, with a helper in namespace pt::grading and another in pt::test
// that collide with nothing the grader links and are the file's own
// (internal linkage: pt-link-guard refuses any external definition in the
// test side's namespaces). The score must not change.
namespace pt::grading {
static int task_file_helper_calls = 0;
}
namespace pt::test {
namespace {
int task_file_seed_note = 0;
}
}  // namespace pt::test
