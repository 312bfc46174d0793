// SPDX-License-Identifier: GPL-3.0-or-later
// What the subcommands that write files share: output paths checked before any work, files
// written whole or not at all, paths quoted for gnuplot and the shell, and the gnuplot run.
//
// A failed write is never silent (issue 11): every file is written to a temporary name in
// its own folder and renamed onto its path only once every byte is flushed, so a full disk
// or an error midway leaves an existing file as it was; an output path that is one of the
// inputs is refused; a path with a control character is refused, because gnuplot reads a
// newline in a path as the end of a command (and the text after it as the next command).
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace roughroll::cli {

// input_error unless `path` can be an output: no control character in it, not a directory,
// not one of `inputs` (the same file, by fs::equivalent), and, when it exists, writable by
// the user ("... is not writable"), as `> FILE` in a shell would require.
void check_output(const std::filesystem::path& path, const std::vector<std::string>& inputs);

// Creates `dir` if needed and returns the absolute path dir/name (without extension),
// checked by check_output; a control character in `dir` is refused before the folder is made.
std::filesystem::path output_stem(const std::string& dir, const std::string& name);

// One output file, written whole or not at all: the text is kept in memory until commit(),
// which writes it to a new temporary file beside `path` (".NAME.tmp-PID-K", created by the
// constructor, so that an unwritable folder is found before any work), closes it and renames
// it onto `path`. Until then `path` is untouched; the destructor removes an uncommitted
// temporary file. A path that exists and is not a regular file (/dev/stdout, /dev/full, a
// FIFO) is written in place. Every failure is an input_error "cannot write 'PATH': <strerror>".
class output_file {
public:
    output_file(std::filesystem::path path, const std::vector<std::string>& inputs);
    output_file(const output_file&) = delete;
    output_file& operator=(const output_file&) = delete;
    ~output_file();

    std::ostream& stream() { return text_; }
    void commit();

private:
    [[noreturn]] void fail(int error) const;

    std::filesystem::path path_;
    std::filesystem::path temporary_;  // empty when written in place
    int fd_ = -1;
    std::ostringstream text_;
    bool committed_ = false;
};

// The files of a plotting subcommand (convergence, traction, figure), opened before any work so that a bad --out
// costs no solve: stem.csv and stem.gp as output_files, stem.svg and stem.png checked for run_gnuplot.
struct plot_files {
    plot_files(std::filesystem::path stem, const std::vector<std::string>& inputs);

    std::filesystem::path stem, csv, script;
    output_file csv_file, script_file;
};

// stdout flushed and checked: input_error "cannot write standard output: <strerror>".
void finish_stdout();

// A path inside a single-quoted gnuplot string (check_output has refused control characters).
std::string gnuplot_path(const std::filesystem::path& p);

// Text inside a double-quoted gnuplot string with enhanced text on: the enhanced-text
// control characters are escaped (\\_ in the script reaches the text processor as \_),
// so that "T_1^(1)" prints as written; " and \ are escaped for the string itself, and a
// backquote is written as its octal escape \140: gnuplot runs `...` as a shell command
// even inside a double-quoted string (a label or a file name must not run anything).
std::string gnuplot_text(const std::string& text);

// The lines a gnuplot script starts with when it writes stem.EXT: `out` is the stem's file
// name, unless the command line set it (run_gnuplot does, to a temporary stem). Every path in
// a script is relative to the script's own folder (its data files lie beside it), so that a
// moved or copied folder can be re-plotted: `cd FOLDER && gnuplot NAME.gp`.
std::string gnuplot_output_stem(const std::filesystem::path& stem);

// Runs gnuplot on the script, in the script's folder (its paths are relative to it), whose images `stem` + each of `extensions` are written under
// a temporary stem and renamed into place when gnuplot succeeds and every image is whole
// (not empty; a PNG ends with its IEND chunk, an SVG with </svg>). A failure is an error with
// gnuplot's own last message, or the image and what is wrong with it, on one line; the
// temporary images are removed and no earlier image is replaced (the data files are written).
void run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& stem,
                 const std::vector<std::string>& extensions);

// Progress of long work on stderr (issue 25): one line per point, row or level, "roughroll: "
// first. Shown when stderr is a terminal or with --progress, never with --quiet; never on
// stdout or in a file, so that the outputs are the same with or without it.
void set_progress(bool on);
bool progress_shown();
void progress(const std::string& line);

}  // namespace roughroll::cli
