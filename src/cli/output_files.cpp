// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/output_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string_view>
#include <system_error>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace roughroll::cli {

namespace fs = std::filesystem;

namespace {

std::string in_quotes(const fs::path& p) { return "'" + one_line(p.string()) + "'"; }

std::string reason(int error) { return error != 0 ? std::strerror(error) : "write failed"; }

bool has_control(const std::string& text) {
    return std::any_of(text.begin(), text.end(),
                       [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

// The path as one single-quoted word for the shell of popen.
std::string shell_word(const std::string& text) {
    std::string out = "'";
    for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// A temporary file beside `path` that did not exist, created here (O_EXCL) and open for
// writing; -1 with `error` set when the folder cannot take it.
int new_temporary(const fs::path& path, fs::path& name, int& error) {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    for (int k = 0; k < 100; ++k) {
        // The file name cut to 200 bytes: the temporary name must stay within NAME_MAX (255).
        name = folder / ("." + path.filename().string().substr(0, 200) + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(k));
        const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return fd;
        if (errno != EEXIST) break;
    }
    error = errno;
    name.clear();
    return -1;
}

// All of `text` to fd, through short writes and interruptions; 0 or the errno of the failure.
int write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n < 0 ? errno : EIO;
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

// The checks of check_output but writability: output_stem's stem is never written itself.
void check_path(const fs::path& path, const std::vector<std::string>& inputs) {
    if (has_control(path.string()))
        throw input_error(
            "output path " + in_quotes(path) +
            " holds a control character: refused (gnuplot would take a newline in it for the end of a command)");
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw input_error("cannot write " + in_quotes(path) + ": it is a directory");
    for (const std::string& input : inputs) {
        if (fs::equivalent(path, input, ec) && !ec)
            throw input_error("output " + in_quotes(path) + " is the input file " + in_quotes(input) +
                              ": refused, it would be overwritten");
    }
}

// A file that exists but that the user could not open for writing (mode 0444, another user's,
// a read-only mount) is refused as the shell's `> FILE` would refuse it: the rename that
// replaces it needs only the folder to be writable, so it would replace the file silently.
// Effective ids (AT_EACCESS), the ones open() is judged by; root passes, as with `>`.
void check_writable(const fs::path& path) {
    if (::faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) == 0 || errno == ENOENT) return;
    const int error = errno;
    std::error_code ec;
    if (!fs::exists(path, ec)) return;  // a dangling symbolic link names a new file
    throw input_error("cannot write " + in_quotes(path) + ": the file exists and is not writable (" + reason(error) +
                      ")");
}

// Why the image gnuplot wrote at `file` is not whole, or "" when it is. gnuplot exits 0 when
// its writes fail (a full disk leaves an empty PNG or an SVG cut midway), so its exit status
// alone cannot tell: a PNG must end with its IEND chunk, an SVG with its closing tag.
std::string image_problem(const fs::path& file, const std::string& extension) {
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status)) return "gnuplot wrote no such image";
    if (!fs::is_regular_file(status)) return "gnuplot's image is not a regular file";
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec) return "cannot read gnuplot's image: " + ec.message();
    if (size == 0) return "gnuplot wrote an empty image (a full disk?)";
    // The end of the file is all the checks need: an incomplete file is cut at its end.
    std::ifstream in(file, std::ios::binary);
    const std::uintmax_t tail_size = std::min<std::uintmax_t>(size, 4096);
    std::string tail(static_cast<std::size_t>(tail_size), '\0');
    in.seekg(static_cast<std::streamoff>(size - tail_size));
    if (!in.read(&tail[0], static_cast<std::streamsize>(tail.size()))) return "cannot read gnuplot's image";
    if (extension == ".png") {
        // The IEND chunk: length 0, type IEND, its CRC.
        static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
        if (tail.size() < iend.size() || tail.compare(tail.size() - iend.size(), iend.size(), iend) != 0)
            return "the PNG gnuplot wrote is incomplete (no IEND chunk at its end; a full disk?)";
    } else if (extension == ".svg") {
        const std::size_t end = tail.find_last_not_of(" \t\r\n");
        const std::string closing = "</svg>";
        if (end == std::string::npos || end + 1 < closing.size() ||
            tail.compare(end + 1 - closing.size(), closing.size(), closing) != 0)
            return "the SVG gnuplot wrote is incomplete (it does not end with </svg>; a full disk?)";
    }
    return "";
}

}  // namespace

void check_output(const fs::path& path, const std::vector<std::string>& inputs) {
    check_path(path, inputs);
    check_writable(path);
}

fs::path output_stem(const std::string& dir, const std::string& name) {
    // Checked before the folder is made: a newline must not create a folder either.
    if (has_control(dir))
        throw input_error("output folder " + in_quotes(dir) +
                          " holds a control character: refused (gnuplot would take "
                          "a newline in it for the end of a command)");
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw input_error("cannot create output folder " + in_quotes(dir) + ": " + ec.message());
    const fs::path stem = fs::absolute(fs::path(dir) / name);
    check_path(stem, {});
    return stem;
}

plot_files::plot_files(fs::path stem_, const std::vector<std::string>& inputs)
    : stem(std::move(stem_)), csv(stem.string() + ".csv"), script(stem.string() + ".gp"), csv_file(csv, inputs),
      script_file(script, inputs) {
    for (const char* ext : {".svg", ".png"}) check_output(stem.string() + ext, inputs);
}

output_file::output_file(fs::path path, const std::vector<std::string>& inputs) : path_(std::move(path)) {
    check_output(path_, inputs);
    std::error_code ec;
    // A symbolic link is followed: the file it names is replaced, the link stays.
    if (fs::is_symlink(path_, ec)) {
        const fs::path target = fs::canonical(path_, ec);
        if (!ec) path_ = target;
    }
    const fs::file_status status = fs::status(path_, ec);
    if (!ec && fs::exists(status) && !fs::is_regular_file(status)) {
        fd_ = ::open(path_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (fd_ < 0) fail(errno);
        return;
    }
    int error = 0;
    fd_ = new_temporary(path_, temporary_, error);
    if (fd_ < 0) fail(error);
    // The new file keeps the mode of the one it replaces.
    if (fs::is_regular_file(status)) ::fchmod(fd_, static_cast<mode_t>(status.permissions()));
}

output_file::~output_file() {
    if (fd_ >= 0) ::close(fd_);
    if (committed_ || temporary_.empty()) return;
    std::error_code ec;
    fs::remove(temporary_, ec);  // nothing more to do if that fails: the path itself is intact
}

void output_file::fail(int error) const {
    throw input_error("cannot write " + in_quotes(path_) + ": " + reason(error));
}

void output_file::commit() {
    const int error = write_all(fd_, text_.str());
    if (error != 0) fail(error);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail(errno);  // NFS and some full disks report here
    if (!temporary_.empty() && std::rename(temporary_.c_str(), path_.c_str()) != 0) fail(errno);
    committed_ = true;
}

void finish_stdout() {
    errno = 0;
    std::cout.flush();
    const bool cout_ok = static_cast<bool>(std::cout);
    const int error = errno;
    if (std::fflush(stdout) != 0 || std::ferror(stdout) || !cout_ok)
        throw input_error("cannot write standard output: " + reason(errno != 0 ? errno : error));
}

std::string gnuplot_path(const fs::path& p) {
    std::string out;
    for (const char c : p.string()) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out;
}

std::string gnuplot_text(const std::string& text) {
    std::string out;
    for (const char c : one_line(text)) {
        if (c == '`') {
            out += "\\140";
        } else if (c == '"') {
            out += "\\\"";
        } else if (c == '\\') {
            out += "\\\\\\\\";
        } else {
            if (std::string_view("^_@&~{}").find(c) != std::string_view::npos) out += "\\\\";
            out += c;
        }
    }
    return out;
}

std::string gnuplot_output_stem(const fs::path& stem) {
    const std::string name = stem.filename().string();
    return "# Paths are relative to this script's folder: re-plot with  cd FOLDER && gnuplot " + name +
           ".gp\n"
           "# The images are out.svg and out.png; gnuplot -e \"out='OTHER'\" writes OTHER.svg, OTHER.png.\n"
           "if (!exists(\"out\")) out = '" +
           gnuplot_path(name) + "'\n";
}

namespace {
bool progress_on = false;
}

void set_progress(bool on) { progress_on = on; }

bool progress_shown() { return progress_on; }

void progress(const std::string& line) {
    if (!progress_on) return;
    // Unbuffered stderr, one whole line per call: it is seen as the work goes on.
    std::cerr << "roughroll: " << echo(line, 300) << std::endl;
}

void run_gnuplot(const fs::path& script, const fs::path& stem, const std::vector<std::string>& extensions) {
    int error = 0;
    fs::path temporary;
    // Absolute: gnuplot runs in the script's folder, where its relative paths point.
    const int fd = new_temporary(fs::absolute(stem), temporary, error);
    if (fd >= 0) ::close(fd);
    if (fd < 0)
        throw input_error("cannot write " + in_quotes(stem.string() + extensions.front()) + ": " + reason(error));
    std::vector<fs::path> images;
    for (const std::string& ext : extensions) images.push_back(temporary.string() + ext);
    const auto clean = [&]() {
        std::error_code ec;
        fs::remove(temporary, ec);
        for (const fs::path& image : images) fs::remove(image, ec);
    };
    // gnuplot's messages are read, not passed to the terminal: one line of them is the reason.
    const fs::path folder = fs::absolute(script).parent_path();
    const std::string command = "cd " + shell_word(folder.string()) + " && gnuplot -e " +
                                shell_word("out='" + gnuplot_path(temporary) + "'") + " " +
                                shell_word(script.filename().string()) + " 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) {
        clean();
        throw numerical_error("cannot run gnuplot: " + reason(errno) + "; the CSV and the script are written");
    }
    std::string output;
    char buffer[4096];
    for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
        if (output.size() < (1u << 20)) output.append(buffer, got);
    const int status = ::pclose(pipe);
    if (status != 0) {
        clean();
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
            throw numerical_error("gnuplot is not installed (or not on PATH): the CSV and the script " +
                                  in_quotes(script) + " are written; --no-plot skips the plot");
        // gnuplot's last non-empty line is its error ("... line 13: all points y value undefined!").
        std::string last;
        std::size_t end = output.size();
        while (last.empty() && end > 0) {
            const std::size_t begin = output.rfind('\n', end - 1);
            const std::size_t from = begin == std::string::npos ? 0 : begin + 1;
            last = output.substr(from, end - from);
            last.erase(0, last.find_first_not_of(" \t\r"));
            end = begin == std::string::npos ? 0 : begin;
        }
        throw numerical_error("gnuplot failed on " + in_quotes(script) + ": " +
                              (last.empty() ? "exit status " + std::to_string(status) : echo(last, 300)) +
                              "; the CSV is written");
    }
    // Every image checked before any is renamed: a failure leaves all of the earlier run's.
    for (std::size_t i = 0; i < extensions.size(); ++i) {
        const std::string problem = image_problem(images[i], extensions[i]);
        if (problem.empty()) continue;
        clean();
        throw input_error("cannot write " + in_quotes(stem.string() + extensions[i]) + ": " + problem +
                          "; no image was replaced");
    }
    for (std::size_t i = 0; i < extensions.size(); ++i) {
        const fs::path target = stem.string() + extensions[i];
        if (std::rename(images[i].c_str(), target.c_str()) != 0) {
            const int e = errno;
            clean();
            throw input_error("cannot write " + in_quotes(target) + ": " + reason(e));
        }
    }
    std::error_code ec;
    fs::remove(temporary, ec);
}

}  // namespace roughroll::cli
