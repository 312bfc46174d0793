// SPDX-License-Identifier: GPL-3.0-or-later
// The validation tests that run the command line: a command's exit status and its whole output, and the scenes they
// write for it.
#pragma once

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

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
