// SPDX-License-Identifier: GPL-3.0-or-later
// The validation tests that run the command line: a command's exit status and its whole output, and the scenes they
// write for it.
#pragma once

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <stdlib.h>
#include <unistd.h>

struct command_output {
    int status;  // pclose's, as from system(3)
    std::string text;
};

inline command_output run_command(const std::string& command) {
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) throw std::runtime_error("popen failed: " + command);
    std::string text;
    char buffer[4096];
    while (const std::size_t got = std::fread(buffer, 1, sizeof buffer, pipe)) text.append(buffer, got);
    return {pclose(pipe), text};
}

// `text` in a new file /tmp/STEM-XXXXXX (mkstemp): its name, empty where none could be made.
inline std::string temporary_file(const std::string& stem, const std::string& text) {
    std::string name = "/tmp/" + stem + "-XXXXXX";
    const int fd = mkstemp(name.data());
    if (fd < 0) return {};
    close(fd);
    std::ofstream(name) << text;
    return name;
}

// The scene file `path` with each `from` replaced by its `to` (the first occurrence of each, in order), in a new
// temporary file (temporary_file with `stem`): its name, empty where a `from` is missing or no file could be made.
inline std::string changed_scene(const std::string& path, const std::vector<std::pair<std::string, std::string>>& changes,
                                 const std::string& stem) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    for (const auto& [from, to] : changes) {
        const std::size_t at = s.find(from);
        if (at == std::string::npos) return {};
        s.replace(at, from.size(), to);
    }
    return temporary_file(stem, s);
}
