// Not an attack: names that only look like one. The task file is the
// solution, with a helper in namespace pt::grading and another in pt::test
// that collide with nothing the grader links. The source flags must show
// them to the instructor, and the score must not change: a flag is for a
// person to read, never a penalty.
namespace pt::grading {
inline int task_file_helper_calls = 0;
}
namespace pt::test {
inline int task_file_seed_note = 0;
}
