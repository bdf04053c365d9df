#include "app/cli.h"

int main(int argc, char** argv) { return pt::run_cli(argc, argv); }
