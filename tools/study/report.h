#pragma once
// The charts (gnuplot, from the CSVs), each experiment's fragment of the page,
// and DIR/index.html with DIR/headline.json.
#include <string>
#include <vector>

#include "study.h"

namespace pt::study {

bool have_gnuplot();
// Writes DIR/<name>.gp (terminal, output and the experiment's script, for PNG
// then SVG) and runs it in DIR. Returns an error message, empty on success.
std::string draw_chart(const Options& opt, const Experiment& e);
// DIR/<name>.html (the experiment's section of the page) and DIR/<name>.json
// (its title, scene, time and headline numbers).
void write_fragment(const Options& opt, const Experiment& e);
// DIR/index.html from the fragments present, in `order`; DIR/headline.json.
void write_index(const Options& opt, const std::vector<std::string>& order, const std::string& machine);

}  // namespace pt::study
