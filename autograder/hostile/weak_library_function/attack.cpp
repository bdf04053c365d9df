// Hostile: replace a function of the C++ library for the whole program with
// a weak definition. std::string::_M_append is exported by libstdc++ and
// called by every std::string append, the worker's link to the verifier
// included; any definition in the program, even a weak one, beats the shared
// library's, so this one would see (and could rewrite) every answer the
// worker sends. The guard let weak mangled definitions through as header
// instantiations. Here it appends honestly: the link is the attack.
#include <cstddef>
#include <string>

std::string& library_append(std::string* self, const char* s, std::size_t n) asm(
    "_ZNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEE9_M_appendEPKcm");
__attribute__((weak)) std::string& library_append(std::string* self, const char* s, std::size_t n) {
  return self->replace(self->size(), 0, s, n);
}
