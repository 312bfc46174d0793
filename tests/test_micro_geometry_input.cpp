// SPDX-License-Identifier: GPL-3.0-or-later
// The micro-geometry reader (micro_geometry_input.hpp) and the profile CSV reader
// (profile_csv.hpp): good input read exactly, every kind of bad input one message naming the
// file and the key or line.
#include "roughroll/io/micro_geometry_input.hpp"
#include "io/micro_geometry_table.hpp"

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "roughroll/io/profile_csv.hpp"

namespace roughroll {
namespace {

namespace fs = std::filesystem;

const std::string source = "spec.toml";

const std::string good = R"(
lambda0 = 1.15e11
mu0 = 7.7e10
H = 1e-5
l = 1e-4
profile = "sine"
delta = 4e-6
decay = "cosine"
)";

// A spec with the line starting with `key =` replaced by `replacement` ("" drops it).
std::string with(const std::string& key, const std::string& replacement, const std::string& base = good) {
    std::string out;
    std::size_t start = 0;
    while (start < base.size()) {
        const std::size_t end = base.find('\n', start);
        const std::string line = base.substr(start, end - start);
        if (line.rfind(key + " =", 0) == 0) {
            if (!replacement.empty()) out += replacement + "\n";
        } else {
            out += line + "\n";
        }
        start = end == std::string::npos ? base.size() : end + 1;
    }
    return out;
}

::testing::AssertionResult message_has(const std::string& message, const std::string& prefix,
                                       std::initializer_list<std::string> fragments) {
    if (message.rfind(prefix, 0) != 0)
        return ::testing::AssertionFailure() << "does not start with " << prefix << ": " << message;
    if (message.find_first_of("\r\n") != std::string::npos)
        return ::testing::AssertionFailure() << "not one line: " << message;
    for (const std::string& f : fragments)
        if (message.find(f) == std::string::npos)
            return ::testing::AssertionFailure() << "'" << f << "' not in: " << message;
    return ::testing::AssertionSuccess() << message;
}

::testing::AssertionResult rejects(const std::string& text, std::initializer_list<std::string> fragments,
                                   const fs::path& base = ".") {
    try {
        (void)parse_roughness_spec(text, source, base);
    } catch (const input_error& e) {
        return message_has(e.what(), source + ":", fragments);
    }
    return ::testing::AssertionFailure() << "accepted:\n" << text;
}

TEST(MicroGeometryInput, GoodSpec) {
    const micro_geometry g = parse_roughness_spec(good, source, ".");
    EXPECT_EQ(g.material.lambda0, 1.15e11);
    EXPECT_EQ(g.material.mu0, 7.7e10);
    EXPECT_EQ(g.material.H, 1e-5);
    EXPECT_EQ(g.material.l, 1e-4);
    EXPECT_EQ(g.bottom.kind, profile_kind::sine);
    EXPECT_EQ(g.bottom.delta, 4e-6);
    EXPECT_EQ(g.shape, micro_shape_kind::sine);
    EXPECT_EQ(g.decay, decay_kind::cosine);
    // Integers are numbers; lambda0 = 0 (Poisson's ratio 0) is allowed.
    const micro_geometry flat = parse_roughness_spec(
        "lambda0 = 0\nmu0 = 1\nH = 1\nl = 2\nprofile = \"flat\"\ndecay = \"linear\"\nmicro_shape = \"sine\"\n", source,
        ".");
    EXPECT_EQ(flat.material.lambda0, 0.0);
    EXPECT_EQ(flat.bottom.kind, profile_kind::flat);
    EXPECT_EQ(parse_roughness_spec(with("profile", "profile = \"sawtooth\""), source, ".").bottom.kind,
              profile_kind::sawtooth);
    EXPECT_EQ(parse_roughness_spec(with("decay", "decay = \"quadratic\""), source, ".").decay, decay_kind::quadratic);
}

// The factor of (2.12) (docs/formulation.md, E11): the derived one unless the spec asks for the
// paper's printed one; any other value or type is refused, naming the key.
TEST(MicroGeometryInput, FactorOf2_12) {
    EXPECT_EQ(parse_roughness_spec(good, source, ".").factor_2_12, normal_factor::derived);
    EXPECT_EQ(parse_roughness_spec(good + "factor_2_12 = \"derived\"\n", source, ".").factor_2_12,
              normal_factor::derived);
    EXPECT_EQ(parse_roughness_spec(good + "factor_2_12 = \"printed\"\n", source, ".").factor_2_12,
              normal_factor::printed);
    EXPECT_TRUE(rejects(good + "factor_2_12 = \"paper\"\n",
                        {"'factor_2_12' must be one of \"derived\", \"printed\" (got \"paper\")"}));
    EXPECT_TRUE(rejects(good + "factor_2_12 = 1\n", {"'factor_2_12' must be a string, not an integer"}));
    const toml::table root = toml::parse("[cylinder1.micro_geometry]\n" + good + "factor_2_12 = \"printed\"\n");
    const toml::table& table = *root["cylinder1"]["micro_geometry"].as_table();
    EXPECT_EQ(read_micro_geometry(table, "scene.toml", "cylinder1.micro_geometry", ".").factor_2_12,
              normal_factor::printed);
}

TEST(MicroGeometryInput, MissingKeys) {
    for (const char* key : {"lambda0", "mu0", "H", "l", "profile", "decay", "delta"}) {
        EXPECT_TRUE(rejects(with(key, ""), {"missing key '" + std::string(key) + "'"}));
    }
}

TEST(MicroGeometryInput, UnknownKeyAndTable) {
    EXPECT_TRUE(rejects(good + "Hx = 1\n", {"unknown key 'Hx'", "allowed here: lambda0"}));
    EXPECT_TRUE(rejects(good + "[layer]\nH = 1\n", {"unknown table 'layer'"}));
}

TEST(MicroGeometryInput, WrongTypes) {
    EXPECT_TRUE(rejects(with("H", "H = \"1e-5\""), {"'H' must be a number, not a string"}));
    EXPECT_TRUE(rejects(with("profile", "profile = 1"), {"'profile' must be a string, not an integer"}));
    EXPECT_TRUE(rejects(with("decay", "decay = true"), {"'decay' must be a string, not a boolean"}));
}

TEST(MicroGeometryInput, BadValues) {
    EXPECT_TRUE(rejects(with("mu0", "mu0 = 0"), {"'mu0' must be finite and > 0 (got 0)"}));
    EXPECT_TRUE(rejects(with("H", "H = -1e-5"), {"'H' must be finite and > 0"}));
    EXPECT_TRUE(rejects(with("l", "l = inf"), {"'l' must be finite and > 0 (got inf)"}));
    EXPECT_TRUE(rejects(with("lambda0", "lambda0 = nan"), {"'lambda0' must be finite and >= 0 (got nan)"}));
    EXPECT_TRUE(rejects(with("lambda0", "lambda0 = -1"), {"'lambda0' must be finite and >= 0"}));
    EXPECT_TRUE(rejects(with("delta", "delta = -1e-6"), {"'delta' must be finite and >= 0"}));
    EXPECT_TRUE(rejects(with("delta", "delta = 1e-5"), {"'delta' = 1e-05 must be < 'H' = 1e-05", "0 <= h0 < H"}));
    EXPECT_TRUE(
        rejects(with("profile", "profile = \"wavy\""), {"'profile' must be one of \"flat\", \"sine\"", "wavy"}));
    EXPECT_TRUE(rejects(with("decay", "decay = \"exp\""), {"'decay' must be one of", "\"cosine\"", "exp"}));
    EXPECT_TRUE(rejects(good + "micro_shape = \"square\"\n", {"'micro_shape' must be one of \"sine\""}));
}

TEST(MicroGeometryInput, KeysOfTheWrongProfile) {
    EXPECT_TRUE(rejects(with("profile", "profile = \"flat\""), {"'delta' is not used by profile = \"flat\""}));
    EXPECT_TRUE(rejects(good + "profile_csv = \"p.csv\"\n", {"'profile_csv' is not used by profile = \"sine\""}));
    const std::string measured = with("delta", "", with("profile", "profile = \"measured\""));
    EXPECT_TRUE(rejects(measured, {"missing key 'profile_csv'"}));
    EXPECT_TRUE(rejects(measured + "profile_csv = \"\"\n", {"'profile_csv' must not be empty"}));
    EXPECT_TRUE(rejects(measured + "profile_csv = \"p.csv\"\ndelta = 1e-6\n",
                        {"'delta' is not used by profile = \"measured\""}));
}

// In a scene's table the messages name the dotted path.
TEST(MicroGeometryInput, NestedTablePaths) {
    const toml::table root = toml::parse("[cylinder1.micro_geometry]\n" + with("H", "H = 0"));
    const toml::table& table = *root["cylinder1"]["micro_geometry"].as_table();
    try {
        (void)read_micro_geometry(table, "scene.toml", "cylinder1.micro_geometry", ".");
        ADD_FAILURE() << "accepted H = 0";
    } catch (const input_error& e) {
        EXPECT_TRUE(message_has(e.what(), "scene.toml:", {"'cylinder1.micro_geometry.H' must be finite and > 0"}));
    }
}

// A temporary folder with a spec and a CSV, for the relative profile_csv.
class MeasuredSpec : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("roughroll-spec-" + std::to_string(::getpid()));
        fs::create_directories(dir_ / "profiles");
    }
    void TearDown() override { fs::remove_all(dir_); }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
    fs::path dir_;
};

const std::string measured_spec =
    "lambda0 = 1\nmu0 = 1\nH = 1\nl = 4\nprofile = \"measured\"\nprofile_csv = \"profiles/p.csv\"\ndecay = "
    "\"linear\"\n";

TEST_F(MeasuredSpec, RelativeCsvIsRelativeToTheSpec) {
    write("profiles/p.csv", "# synthetic\nx1,h0\n0,0.1\n1,0.2\n2,0.3\n3,0.2\n4,0.1\n");
    write("spec.toml", measured_spec);
    const micro_geometry g = read_roughness_spec((dir_ / "spec.toml").string());
    ASSERT_EQ(g.bottom.kind, profile_kind::measured);
    EXPECT_EQ(g.bottom.measured.x1, (std::vector<double>{0, 1, 2, 3}));  // the closing point dropped
    EXPECT_EQ(g.bottom.measured.h0, (std::vector<double>{0.1, 0.2, 0.3, 0.2}));
    EXPECT_EQ(g.bottom.measured.lines, (std::vector<int>{3, 4, 5, 6}));
}

TEST_F(MeasuredSpec, CsvErrorsNameFileAndLine) {
    write("profiles/p.csv", "x1,h0\n0,0.1\n1,0.2\n2,abc\n3,0.2\n");
    write("spec.toml", measured_spec);
    try {
        (void)read_roughness_spec((dir_ / "spec.toml").string());
        ADD_FAILURE() << "accepted a bad CSV";
    } catch (const input_error& e) {
        // The spec and its key first, then the CSV's own file and line.
        const std::string csv = (dir_ / "profiles" / "p.csv").string();
        const std::string spec = (dir_ / "spec.toml").string() + ": 'profile_csv': ";
        EXPECT_TRUE(message_has(e.what(), spec + csv + ":4:", {"h0 'abc' is not a number"}));
    }
    fs::remove(dir_ / "profiles" / "p.csv");
    try {
        (void)read_roughness_spec((dir_ / "spec.toml").string());
        ADD_FAILURE() << "accepted a missing CSV";
    } catch (const input_error& e) {
        EXPECT_TRUE(message_has(e.what(), (dir_ / "spec.toml").string() + ": 'profile_csv': cannot read profile file",
                                {"p.csv", "No such file"}));
    }
    // A sample at or above H: the line named.
    write("profiles/p.csv", "0,0.1\n1,0.2\n2,1.5\n3,0.2\n");
    try {
        (void)read_roughness_spec((dir_ / "spec.toml").string());
        ADD_FAILURE() << "accepted h0 >= H";
    } catch (const input_error& e) {
        EXPECT_TRUE(
            message_has(e.what(), (dir_ / "profiles" / "p.csv").string() + ":3:", {"h0 = 1.5", "not below H = 1"}));
    }
}

// parse_profile_csv: the message for `text` (period 4), checked to start with "p.csv:<line>:".
::testing::AssertionResult csv_rejects(const std::string& text, const std::string& where,
                                       std::initializer_list<std::string> fragments) {
    try {
        (void)parse_profile_csv(text, "p.csv", 4.0);
    } catch (const input_error& e) {
        return message_has(e.what(), "p.csv" + where + ": ", fragments);
    }
    return ::testing::AssertionFailure() << "accepted:\n" << text;
}

TEST(ProfileCsv, Accepts) {
    // Comments, blank lines, CRLF, spaces, an integer, an exponent, no header.
    const profile_samples s =
        parse_profile_csv("  # comment\r\n\r\n0 , 1e-1\r\n1,0.2\n 2.5 ,3\n3.0,0.25", "p.csv", 4.0);
    EXPECT_EQ(s.x1, (std::vector<double>{0, 1, 2.5, 3}));
    EXPECT_EQ(s.h0, (std::vector<double>{0.1, 0.2, 3, 0.25}));
    EXPECT_EQ(s.lines, (std::vector<int>{3, 4, 5, 6}));
    EXPECT_EQ(s.source, "p.csv");
    // The header with spaces; the closing point repeating the first h0.
    EXPECT_EQ(parse_profile_csv(" x1 , h0 \n0,1\n1,2\n2,3\n3,2\n4,1\n", "p.csv", 4.0).x1.size(), 4u);
    // A UTF-8 byte-order mark before the header (spreadsheet exports).
    EXPECT_EQ(parse_profile_csv("\xEF\xBB\xBFx1,h0\n0,1\n1,2\n2,3\n3,2\n", "p.csv", 4.0).x1.size(), 4u);
}

TEST(ProfileCsv, EachBadLine) {
    EXPECT_TRUE(csv_rejects("x,h\n0,1\n", ":1", {"x1 'x' is not a number", "the only header allowed is 'x1,h0'"}));
    EXPECT_TRUE(csv_rejects("0,1\n1,2,3\n", ":2", {"expected two comma-separated fields"}));
    EXPECT_TRUE(csv_rejects("0;1\n", ":1", {"expected two comma-separated fields"}));
    EXPECT_TRUE(csv_rejects("0,1\n1,\n", ":2", {"h0 '' is not a number"}));
    EXPECT_TRUE(csv_rejects("0,1\n1,2x\n", ":2", {"h0 '2x' is not a number"}));
    EXPECT_TRUE(csv_rejects("0,1\n+1,2\n", ":2", {"x1 '+1' is not a number"}));
    EXPECT_TRUE(csv_rejects("0,1\nx1,h0\n", ":2", {"x1 'x1' is not a number"}));  // a header only first
    EXPECT_TRUE(csv_rejects("0,1\n1,nan\n", ":2", {"h0 = nan is not finite"}));
    EXPECT_TRUE(csv_rejects("0,1\ninf,1\n", ":2", {"x1 = inf is not finite"}));
    EXPECT_TRUE(csv_rejects("# c\n0.5,1\n", ":2", {"the first sample must be at x1 = 0 (got x1 = 0.5)"}));
    EXPECT_TRUE(csv_rejects("0,1\n2,1\n2,1\n", ":3", {"x1 = 2 does not increase"}));
    EXPECT_TRUE(csv_rejects("0,1\n2,1\n1,1\n", ":3", {"x1 = 1 does not increase"}));
    EXPECT_TRUE(csv_rejects("0,1\n1,1\n2,1\n5,1\n", ":4", {"x1 = 5 is beyond the period l = 4"}));
    EXPECT_TRUE(
        csv_rejects("0,1\n1,1\n2,1\n3,1\n4,2\n", ":5", {"closing point x1 = l = 4 has h0 = 2, not the h0 = 1"}));
    EXPECT_TRUE(csv_rejects("0,1\n1,1\n2,1\n3,1\n4,1\n5,1\n", ":6", {"a sample after the closing point"}));
    EXPECT_TRUE(csv_rejects("0,1\n1,1\n2,1\n", "", {"at least 4 samples", "got 3"}));
    EXPECT_TRUE(csv_rejects("0,1\n1,1\n2,1\n4,1\n", "", {"at least 4 samples", "got 3"}));  // closing point not counted
    EXPECT_TRUE(csv_rejects("", "", {"got 0"}));
    EXPECT_TRUE(csv_rejects("0,1\n1,\001\n", ":2", {"h0 '\\x01' is not a number"}));
}

// A measured profile as arrays (issue 25: Python's NumPy arrays of the CSV's columns): the same
// samples as the CSV, and the CSV's rules, each sample named by its index.
const std::string array_spec = "lambda0 = 1\nmu0 = 1\nH = 1\nl = 4\nprofile = \"measured\"\ndecay = \"linear\"\n";

TEST_F(MeasuredSpec, ArraysAreTheCsvsSamples) {
    write("profiles/p.csv", "x1,h0\n0,0.1\n1,0.2\n2,0.3\n3,0.2\n4,0.1\n");
    write("spec.toml", measured_spec);
    const micro_geometry csv = read_roughness_spec((dir_ / "spec.toml").string());
    const micro_geometry arrays = parse_roughness_spec(
        array_spec + "profile_x1 = [0, 1.0, 2, 3, 4]\nprofile_h0 = [0.1, 0.2, 0.3, 0.2, 0.1]\n", source, ".");
    EXPECT_EQ(arrays.bottom.measured.x1, csv.bottom.measured.x1);  // the closing point dropped
    EXPECT_EQ(arrays.bottom.measured.h0, csv.bottom.measured.h0);
    EXPECT_EQ(arrays.bottom.measured.lines, (std::vector<int>{0, 1, 2, 3}));
}

TEST(MicroGeometryInput, ArrayMistakes) {
    const std::string x4 = "profile_x1 = [0, 1, 2, 3]\n", h4 = "profile_h0 = [0.1, 0.2, 0.3, 0.2]\n";
    EXPECT_TRUE(rejects(array_spec + x4, {"missing key 'profile_h0'"}));
    EXPECT_TRUE(rejects(array_spec + x4 + "profile_h0 = [0.1, 0.2, 0.3]\n",
                        {"'profile_x1' has 4 samples but 'profile_h0' has 3"}));
    EXPECT_TRUE(rejects(array_spec + "profile_x1 = [0, 1, 2]\nprofile_h0 = [0.1, 0.2, 0.3]\n",
                        {"needs at least 4 samples", "'profile_x1' has 3"}));
    EXPECT_TRUE(rejects(array_spec + "profile_x1 = [0, 1, nan, 3]\n" + h4,
                        {"'profile_x1' and 'profile_h0' at index:2: x1 = nan is not finite"}));
    EXPECT_TRUE(rejects(array_spec + x4 + "profile_h0 = [0.1, inf, 0.3, 0.2]\n", {"index:1: h0 = inf is not finite"}));
    EXPECT_TRUE(rejects(array_spec + "profile_x1 = [0, 2, 1, 3]\n" + h4, {"index:2: x1 = 1 does not increase"}));
    EXPECT_TRUE(
        rejects(array_spec + "profile_x1 = [1, 2, 3, 3.5]\n" + h4, {"index:0: the first sample must be at x1 = 0"}));
    EXPECT_TRUE(
        rejects(array_spec + "profile_x1 = [0, 1, 2, 5]\n" + h4, {"index:3: x1 = 5 is beyond the period l = 4"}));
    EXPECT_TRUE(rejects(array_spec + x4 + "profile_h0 = [0.1, -0.2, 0.3, 0.2]\n", {"index:1: h0 = -0.2 is below 0"}));
    EXPECT_TRUE(rejects(array_spec + "profile_x1 = [0, 1, \"2\", 3]\n" + h4, {"'profile_x1[2]' must be a number"}));
    EXPECT_TRUE(rejects(array_spec + "profile_x1 = 0\n" + h4, {"'profile_x1' must be an array of numbers"}));
    EXPECT_TRUE(rejects(array_spec + x4 + h4 + "profile_csv = \"p.csv\"\n", {"not both"}));
    EXPECT_TRUE(rejects(good + x4 + h4, {"'profile_x1' is not used by profile = \"sine\""}));
}

}  // namespace
}  // namespace roughroll
