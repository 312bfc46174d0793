// Subcommands of the CLI that live in their own files.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace roughroll::cli {

struct figure_options {
    std::string which;      // "2a" or "2b"
    std::string out = "figures";
    int points = 101;       // creep points per curve
    int n = 0;              // 0: the method's default
    std::string method_name = "product";
    bool plot = true;
};

void add_figure_options(CLI::App* cmd, figure_options& o);
int run_figure(const figure_options& o);

}  // namespace roughroll::cli
