// What the plotting subcommands share: an output folder, paths quoted for gnuplot and
// the shell, and the gnuplot run itself.
#pragma once

#include <filesystem>
#include <string>

namespace roughroll::cli {

// Creates `dir` if needed and returns the absolute path dir/name (without extension).
std::filesystem::path output_stem(const std::string& dir, const std::string& name);

// A path inside a single-quoted gnuplot string.
std::string gnuplot_path(const std::filesystem::path& p);

// Runs gnuplot on the script; numerical_error when it fails (the data files are written).
void run_gnuplot(const std::filesystem::path& script);

}  // namespace roughroll::cli
