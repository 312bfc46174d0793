#include "cli/output_files.hpp"

#include <cstdlib>
#include <system_error>

#include "roughroll/base/error.hpp"

namespace roughroll::cli {

std::filesystem::path output_stem(const std::string& dir, const std::string& name) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw input_error("cannot create output folder '" + dir + "': " + ec.message());
    return std::filesystem::absolute(std::filesystem::path(dir) / name);
}

std::string gnuplot_path(const std::filesystem::path& p) {
    std::string out;
    for (const char c : p.string()) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out;
}

void run_gnuplot(const std::filesystem::path& script) {
    // The script's path as one single-quoted word for the shell of std::system.
    std::string quoted = "'";
    for (const char c : script.string()) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    const std::string command = "gnuplot " + quoted + "'";
    if (std::system(command.c_str()) != 0)
        throw numerical_error("gnuplot failed on '" + script.string() + "' (is gnuplot installed?); the CSV is written");
}

}  // namespace roughroll::cli
