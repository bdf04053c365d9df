#pragma once
// The worker's end of the link (worker_main.cpp), for the codecs whose
// objects call back into the verifier while the student's code runs.
#include "wire.h"

namespace pt::boundary {

Link& worker_link();

}  // namespace pt::boundary
