// Hostile: bring a header of one's own. The zip holds the part's task file
// and include/core/not_implemented.h, a copy of the framework's header whose
// NotImplemented throws nothing, in the hope that it lands on the include
// path ahead of the real one and turns every stub's throw into a pass.
