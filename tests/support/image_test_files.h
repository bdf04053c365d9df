#pragma once
// What an image test leaves behind when it fails, for a person to look at:
// the render, the (block-averaged) reference, their difference and a p-value
// map, as PNGs enlarged to the stored image's size (linear EXRs of the render
// and reference at the test's size too), one folder per test, in the folder
// given by the test binary's --pt_image_dir=DIR (pt-grade's: it takes the
// PNGs into its HTML report), else $PT_IMAGE_TEST_DIR, else
// ./image_test_failures/. The message names the folder by its absolute path.
// Where it cannot be written, the message says so; the verdict does not
// depend on it.
#include <string>

#include "support/image_test.h"

namespace pt::image_test {

// The folder of --pt_image_dir (support/test_main.cpp): before any test runs.
void set_failure_image_dir(const std::string& dir);

// Writes the images; returns a sentence for the failure message naming the
// folder and what each file shows (or why nothing was written).
std::string write_failure_images(const Result& r);

// Each cell of the finest grid: its smallest p (any channel, either sum), as
// grey from black (p = 1) to white (p = alpha_each) on a log scale, and red
// where p < alpha_each (the coarser regions' p are in the message).
Image p_value_image(const Result& r);

}  // namespace pt::image_test
