#pragma once
// A planted crossing for framework:layers-catches (core may not include render/).
#include "render/renderer.h"
