// Hostile: a weak copy of a comparison helper of the test support. The Part 1
// tests compare through pt::test::Near and VecNear, inline functions of
// support/assertions.h, so each test object holds a weak (COMDAT) copy;
// the linker keeps the first copy it meets, and the task file's came first.
// This one says every comparison holds. The name is given in assembler
// (AssertionResult is returned through a hidden pointer: {bool success;
// message pointer}), so no GoogleTest declaration is needed.
struct PtAssertionResult {
  bool success;
  void* message;
};
__attribute__((weak, used)) PtAssertionResult* pt_near_always(PtAssertionResult* out, const char*, double, double,
                                                        double) __asm__("_ZN2pt4test4NearEPKcddd");
PtAssertionResult* pt_near_always(PtAssertionResult* out, const char*, double, double, double) {
  out->success = true;
  out->message = nullptr;
  return out;
}
