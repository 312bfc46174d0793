// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/scene.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "roughroll/base/error.hpp"
#include "tolerance.hpp"

namespace roughroll {
namespace {

const std::string source = "scene.toml";

// The message parse_scene throws for `text`, checked to be one line that starts
// with the source and contains every fragment.
::testing::AssertionResult rejects(const std::string& text, std::initializer_list<std::string> fragments) {
    try {
        (void)parse_scene(text, source);
    } catch (const input_error& e) {
        const std::string message = e.what();
        if (message.rfind(source + ":", 0) != 0) {
            return ::testing::AssertionFailure() << "does not start with the source: " << message;
        }
        if (message.find('\n') != std::string::npos || message.find('\r') != std::string::npos) {
            return ::testing::AssertionFailure() << "not one line: " << message;
        }
        for (const std::string& fragment : fragments) {
            if (message.find(fragment) == std::string::npos) {
                return ::testing::AssertionFailure() << "'" << fragment << "' not in: " << message;
            }
        }
        return ::testing::AssertionSuccess() << message;
    }
    return ::testing::AssertionFailure() << "accepted:\n" << text;
}

// The message load_of throws, or "" when it returns.
std::string load_error(const scene& s, std::optional<double> override) {
    try {
        (void)load_of(s, override);
    } catch (const input_error& e) {
        return e.what();
    }
    return "";
}

const std::string full_scene = R"(
label = "Fig. 2a, curve 2"
friction = 0.3
Q = 0.15
[cylinder1.tangential]
T = 0.5
A = 0.25
[cylinder1.normal]
T = 0.75
A = 1.5
[cylinder2.tangential]
T = 2.0
A = 3.0
[cylinder2.normal]
T = 4.0
A = 5.0
[solver]
n = 321
method = "product"
)";

TEST(Scene, FullScene) {
    const scene s = parse_scene(full_scene, source);
    EXPECT_EQ(s.label, "Fig. 2a, curve 2");
    EXPECT_DOUBLE_EQ(s.friction, 0.3);
    ASSERT_TRUE(s.Q.has_value());
    EXPECT_DOUBLE_EQ(*s.Q, 0.15);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder1.tangential.T, 0.5);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder1.tangential.A, 0.25);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder1.normal.T, 0.75);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder1.normal.A, 1.5);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder2.tangential.T, 2.0);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder2.tangential.A, 3.0);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder2.normal.T, 4.0);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder2.normal.A, 5.0);
    EXPECT_FALSE(s.surfaces.smooth());
    EXPECT_EQ(s.solver.n, 321);
    EXPECT_EQ(s.solver.how, method::product);
}

TEST(Scene, Defaults) {
    const scene s = parse_scene("friction = 0.3\n", source);
    EXPECT_EQ(s.label, "");
    EXPECT_DOUBLE_EQ(s.friction, 0.3);
    EXPECT_FALSE(s.Q.has_value());
    EXPECT_TRUE(s.surfaces.smooth());
    EXPECT_EQ(s.surfaces.cylinder1.normal.A, 0.0);
    EXPECT_EQ(s.solver.n, 0);  // unset: the method's default
    EXPECT_EQ(s.solver.how, method::extrapolated);
    EXPECT_EQ(s.solver.nodes(), default_nodes(method::extrapolated));
}

TEST(Scene, EmptyTablesKeepDefaults) {
    const scene s = parse_scene("friction = 0.3\n[cylinder1]\n[solver]\n", source);
    EXPECT_TRUE(s.surfaces.smooth());
    EXPECT_EQ(s.solver.n, 0);  // unset: the method's default
    EXPECT_EQ(s.solver.how, method::extrapolated);
    EXPECT_EQ(s.solver.nodes(), default_nodes(method::extrapolated));
}

TEST(Scene, OnlyOneTermOfOneCylinder) {
    const scene s = parse_scene("friction = 0.3\n[cylinder2.normal]\nT = 0.5\nA = 0.125\n", source);
    EXPECT_FALSE(s.surfaces.cylinder1.tangential.present());
    EXPECT_FALSE(s.surfaces.cylinder1.normal.present());
    EXPECT_FALSE(s.surfaces.cylinder2.tangential.present());
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder2.normal.T, 0.5);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder2.normal.A, 0.125);
}

TEST(Scene, IntegersWhereNumbersAreExpected) {
    const scene s = parse_scene("friction = 1\nQ = -1\n[cylinder1.normal]\nT = 1\nA = 0\n", source);
    EXPECT_EQ(s.friction, 1.0);
    ASSERT_TRUE(s.Q.has_value());
    EXPECT_EQ(*s.Q, -1.0);
    EXPECT_EQ(s.surfaces.cylinder1.normal.T, 1.0);
    EXPECT_EQ(s.surfaces.cylinder1.normal.A, 0.0);
}

TEST(Scene, InlineTablesAreTables) {
    const scene s = parse_scene("friction = 0.3\ncylinder1 = { tangential = { T = 2, A = 0.5 } }\n", source);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder1.tangential.T, 2.0);
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder1.tangential.A, 0.5);
}

TEST(Scene, NodeCountLimitsAccepted) {
    EXPECT_EQ(parse_scene("friction = 0.3\n[solver]\nn = 2\n", source).solver.n, 2);
    EXPECT_EQ(parse_scene("friction = 0.3\n[solver]\nn = 1000\n", source).solver.n, 1000);
}

TEST(Scene, LoadAtTheFrictionLimitAccepted) {
    EXPECT_EQ(*parse_scene("friction = 0.3\nQ = 0.3\n", source).Q, 0.3);
    EXPECT_EQ(*parse_scene("friction = 0.3\nQ = -0.3\n", source).Q, -0.3);
    EXPECT_EQ(*parse_scene("friction = 0.3\nQ = 0\n", source).Q, 0.0);
}

TEST(Scene, MissingFriction) {
    EXPECT_TRUE(rejects("Q = 0.1\n", {"scene.toml: missing key 'friction'"}));
    EXPECT_TRUE(rejects("", {"missing key 'friction'"}));
}

TEST(Scene, NonNumbersWhereNumbersAreExpected) {
    EXPECT_TRUE(rejects("friction = \"0.3\"\n", {"scene.toml: 'friction' must be a number, not a string"}));
    EXPECT_TRUE(rejects("friction = true\n", {"'friction' must be a number, not a boolean"}));
    EXPECT_TRUE(rejects("friction = [0.3]\n", {"'friction' must be a number, not an array"}));
    EXPECT_TRUE(rejects("friction = {}\n", {"'friction' must be a number, not a table"}));
    EXPECT_TRUE(rejects("friction = 1979-05-27\n", {"'friction' must be a number, not a date"}));
    EXPECT_TRUE(rejects("friction = 0.3\nQ = \"0.1\"\n", {"'Q' must be a number, not a string"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.normal]\nT = \"1\"\nA = 1\n",
                        {"'cylinder1.normal.T' must be a number, not a string"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder2.tangential]\nT = 1\nA = false\n",
                        {"'cylinder2.tangential.A' must be a number, not a boolean"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.tangential]\nT = [1]\nA = 1\n",
                        {"'cylinder1.tangential.T' must be a number, not an array"}));
}

TEST(Scene, FrictionMustBeFiniteAndPositive) {
    EXPECT_TRUE(rejects("friction = 0\n", {"'friction' must be finite and > 0 (got 0)"}));
    EXPECT_TRUE(rejects("friction = -0.0\n", {"'friction' must be finite and > 0 (got -0)"}));
    EXPECT_TRUE(rejects("friction = -1\n", {"'friction' must be finite and > 0 (got -1)"}));
    EXPECT_TRUE(rejects("friction = nan\n", {"'friction' must be finite and > 0 (got ", "nan)"}));
    EXPECT_TRUE(rejects("friction = inf\n", {"'friction' must be finite and > 0 (got inf)"}));
    EXPECT_TRUE(rejects("friction = -inf\n", {"'friction' must be finite and > 0 (got -inf)"}));
}

TEST(Scene, RoughnessMustBeFiniteAndNonNegative) {
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.normal]\nT = 1\nA = -1\n",
                        {"scene.toml: 'cylinder1.normal.A' must be finite and >= 0 (got -1)"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.tangential]\nT = -0.5\nA = 1\n",
                        {"'cylinder1.tangential.T' must be finite and >= 0 (got -0.5)"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder2.normal]\nT = nan\nA = 1\n",
                        {"'cylinder2.normal.T' must be finite and >= 0 (got ", "nan)"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder2.tangential]\nT = 1\nA = inf\n",
                        {"'cylinder2.tangential.A' must be finite and >= 0 (got inf)"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder2.tangential]\nT = -inf\nA = 1\n",
                        {"'cylinder2.tangential.T' must be finite and >= 0 (got -inf)"}));
}

TEST(Scene, RoughnessZeroAccepted) {
    const scene s = parse_scene("friction = 0.3\n[cylinder1.normal]\nT = 0\nA = -0.0\n", source);
    EXPECT_FALSE(s.surfaces.cylinder1.normal.present());
    EXPECT_TRUE(s.surfaces.smooth());
}

TEST(Scene, TermNeedsBothTAndA) {
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.normal]\nT = 1\n",
                        {"scene.toml: table 'cylinder1.normal' needs both T and A (missing 'A')"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder2.tangential]\nA = 1\n",
                        {"table 'cylinder2.tangential' needs both T and A (missing 'T')"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.tangential]\n",
                        {"table 'cylinder1.tangential' needs both T and A (missing 'T')"}));
}

TEST(Scene, LoadMustBeFiniteAndCarriedByFriction) {
    EXPECT_TRUE(
        rejects("friction = 0.3\nQ = 0.4\n", {"scene.toml: 'Q'", "|Q| = 0.4 exceeds f = 0.3: the cylinders slide"}));
    EXPECT_TRUE(rejects("friction = 0.3\nQ = -0.4\n", {"'Q'", "|Q| = 0.4 exceeds f = 0.3", "slide"}));
    EXPECT_TRUE(rejects("friction = 0.3\nQ = nan\n", {"'Q' must be finite (got ", "nan)"}));
    EXPECT_TRUE(rejects("friction = 0.3\nQ = inf\n", {"'Q' must be finite (got inf)"}));
    EXPECT_TRUE(rejects("friction = 0.3\nQ = -inf\n", {"'Q' must be finite (got -inf)"}));
}

TEST(Scene, UnknownKeyAtTopLevel) {
    EXPECT_TRUE(rejects("friction = 0.3\nfrction = 0.3\n", {"scene.toml: unknown key 'frction'", "friction"}));
    // Case matters: q is not Q.
    EXPECT_TRUE(rejects("friction = 0.3\nq = 0.1\n", {"unknown key 'q'"}));
}

TEST(Scene, UnknownKeyInsideCylinder) {
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1]\nrough = true\n", {"unknown key 'cylinder1.rough'"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder2.normals]\nT = 1\nA = 1\n", {"unknown table 'cylinder2.normals'"}));
}

TEST(Scene, UnknownKeyInsideTerm) {
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.normal]\nT = 1\nA = 1\nTx = 1\n",
                        {"scene.toml: unknown key 'cylinder1.normal.Tx'"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.normal.extra]\n", {"unknown table 'cylinder1.normal.extra'"}));
}

TEST(Scene, UnknownKeyInsideSolver) {
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\ntol = 1e-9\n", {"unknown key 'solver.tol'"}));
}

TEST(Scene, UnknownTable) {
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder3.normal]\nT = 1\nA = 1\n", {"unknown table 'cylinder3'"}));
}

TEST(Scene, NonTableWhereTableIsExpected) {
    EXPECT_TRUE(rejects("friction = 0.3\ncylinder1 = 3\n", {"'cylinder1' must be a table, not an integer"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder2]\nnormal = 0.5\n",
                        {"'cylinder2.normal' must be a table, not a floating-point number"}));
    EXPECT_TRUE(rejects("friction = 0.3\nsolver = \"fast\"\n", {"'solver' must be a table, not a string"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[[cylinder1]]\n", {"'cylinder1' must be a table, not an array"}));
}

TEST(Scene, NodeCountMustBeAnIntegerInRange) {
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\nn = 200.0\n",
                        {"scene.toml: 'solver.n' must be an integer", "floating-point"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\nn = \"200\"\n", {"'solver.n' must be an integer, not a string"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\nn = 5000\n", {"'solver.n' = 5000 is outside [2, 1000]"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\nn = 1\n", {"'solver.n' = 1 is outside [2, 1000]"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\nn = -3\n", {"'solver.n' = -3 is outside [2, 1000]"}));
    // Beyond int: must not wrap around into the range when narrowed.
    EXPECT_TRUE(
        rejects("friction = 0.3\n[solver]\nn = 4294967496\n", {"'solver.n' = 4294967496 is outside [2, 1000]"}));
}

TEST(Scene, MethodMustBeAKnownName) {
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\nmethod = \"foo\"\n",
                        {"scene.toml: 'solver.method'", "unknown method 'foo'"}));
    EXPECT_TRUE(
        rejects("friction = 0.3\n[solver]\nmethod = 1\n", {"'solver.method' must be a string, not an integer"}));
    EXPECT_EQ(parse_scene("friction = 0.3\n[solver]\nmethod = \"paper\"\n", source).solver.how, method::paper);
}

TEST(Scene, LabelMustBeAString) {
    EXPECT_TRUE(rejects("label = 3\nfriction = 0.3\n", {"'label' must be a string, not an integer"}));
}

TEST(Scene, MalformedToml) {
    EXPECT_TRUE(rejects("friction = \n", {"scene.toml:1:", "malformed TOML"}));
    EXPECT_TRUE(rejects("label = \"x\"\nfriction = \n", {"scene.toml:2:", "malformed TOML"}));
    EXPECT_TRUE(rejects("friction = 0.3\nfriction = 0.4\n", {"scene.toml:2:", "malformed TOML"}));
    EXPECT_TRUE(rejects("friction = 0.3 0.4\n", {"scene.toml:1:", "malformed TOML"}));
}

TEST(Scene, TruncatedToml) {
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1.norm", {"scene.toml:2:", "malformed TOML"}));
    EXPECT_TRUE(rejects("friction = 0.3\nlabel = \"unterminated", {"scene.toml:2:", "malformed TOML"}));
    EXPECT_TRUE(rejects("friction = 0.3\ncylinder1 = { normal = { T = 1", {"scene.toml:2:", "malformed TOML"}));
}

TEST(Scene, MessagesStayOnOneLine) {
    // A quoted key may hold a newline; the message must still be one line.
    EXPECT_TRUE(rejects("friction = 0.3\n\"a\\nb\" = 1\n", {"unknown key 'a\\x0ab'"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\nmethod = \"pa\\nper\"\n", {"unknown method 'pa\\x0aper'"}));
}

// A file in the test's temporary directory, removed at the end of the test.
class temp_file {
public:
    temp_file(const std::string& name, const std::string& text)
        : path_(std::filesystem::path(::testing::TempDir()) /
                ("roughroll_" + std::to_string(::getpid()) + "_" + name)) {
        std::ofstream(path_) << text;
    }
    ~temp_file() {
        std::error_code ignored;
        std::filesystem::permissions(path_, std::filesystem::perms::owner_all, ignored);
        std::filesystem::remove(path_, ignored);
    }
    temp_file(const temp_file&) = delete;
    temp_file& operator=(const temp_file&) = delete;
    std::string path() const { return path_.string(); }

private:
    std::filesystem::path path_;
};

std::string read_error(const std::string& path) {
    try {
        (void)read_scene(path);
    } catch (const input_error& e) {
        return e.what();
    }
    return "";
}

TEST(ReadScene, ValidFile) {
    const temp_file file("valid.toml", full_scene);
    const scene s = read_scene(file.path());
    EXPECT_EQ(s.label, "Fig. 2a, curve 2");
    EXPECT_DOUBLE_EQ(s.surfaces.cylinder1.normal.A, 1.5);
    EXPECT_EQ(s.solver.n, 321);
}

TEST(ReadScene, MessagesNameTheFile) {
    const temp_file file("bad.toml", "friction = 0.3\nQ = 0.5\n");
    const std::string message = read_error(file.path());
    EXPECT_EQ(message.rfind(file.path() + ": 'Q'", 0), 0u) << message;
    EXPECT_NE(message.find("the cylinders slide"), std::string::npos) << message;

    const temp_file broken("broken.toml", "friction = \n");
    const std::string syntax = read_error(broken.path());
    EXPECT_EQ(syntax.rfind(broken.path() + ":1:", 0), 0u) << syntax;
    EXPECT_NE(syntax.find("malformed TOML"), std::string::npos) << syntax;
}

TEST(ReadScene, MissingFile) {
    const std::string path = ::testing::TempDir() + "/roughroll_no_such_scene.toml";
    const std::string message = read_error(path);
    EXPECT_EQ(message.rfind("cannot read scene file '" + path + "': ", 0), 0u) << message;
    EXPECT_NE(message.find("No such file"), std::string::npos) << message;
}

TEST(ReadScene, Directory) {
    const std::string path = ::testing::TempDir();
    const std::string message = read_error(path);
    EXPECT_EQ(message.rfind("cannot read scene file '" + path + "': ", 0), 0u) << message;
    EXPECT_NE(message.find("directory"), std::string::npos) << message;
}

TEST(ReadScene, NotARegularFile) {
    const std::string message = read_error("/dev/null");
    EXPECT_EQ(message, "cannot read scene file '/dev/null': it is not a regular file");
}

TEST(ReadScene, UnreadableFile) {
    if (::geteuid() == 0) GTEST_SKIP() << "root reads files whatever their permissions";
    const temp_file file("unreadable.toml", "friction = 0.3\n");
    std::filesystem::permissions(file.path(), std::filesystem::perms::none);
    const std::string message = read_error(file.path());
    EXPECT_EQ(message.rfind("cannot read scene file '" + file.path() + "': ", 0), 0u) << message;
    EXPECT_NE(message.find("ermission"), std::string::npos) << message;
}

scene with_friction(double f, std::optional<double> Q) {
    scene s;
    s.friction = f;
    s.Q = Q;
    return s;
}

TEST(LoadOf, OverrideWins) {
    EXPECT_EQ(load_of(with_friction(0.3, 0.1), 0.2), 0.2);
    EXPECT_EQ(load_of(with_friction(0.3, 0.1), -0.25), -0.25);
}

TEST(LoadOf, SceneLoadWithoutOverride) { EXPECT_EQ(load_of(with_friction(0.3, 0.1), std::nullopt), 0.1); }

TEST(LoadOf, NoLoadGiven) {
    EXPECT_EQ(load_error(with_friction(0.3, std::nullopt), std::nullopt),
              "no load Q given: set Q (or Q_over_f) in the scene or pass --Q (or --Q-over-f)");
}

TEST(LoadOf, LimitsAccepted) {
    EXPECT_EQ(load_of(with_friction(0.3, std::nullopt), 0.0), 0.0);
    EXPECT_EQ(load_of(with_friction(0.3, std::nullopt), 0.3), 0.3);
    EXPECT_EQ(load_of(with_friction(0.3, std::nullopt), -0.3), -0.3);
    EXPECT_EQ(load_of(with_friction(0.3, 0.3), std::nullopt), 0.3);
}

TEST(LoadOf, OverrideMustBeFinite) {
    const scene s = with_friction(0.3, 0.1);
    const std::string nan = load_error(s, std::numeric_limits<double>::quiet_NaN());
    EXPECT_EQ(nan.rfind("Q must be finite (got ", 0), 0u) << nan;
    EXPECT_NE(nan.find("nan"), std::string::npos) << nan;
    EXPECT_EQ(load_error(s, std::numeric_limits<double>::infinity()), "Q must be finite (got inf)");
    EXPECT_EQ(load_error(s, -std::numeric_limits<double>::infinity()), "Q must be finite (got -inf)");
}

TEST(LoadOf, CylindersSlide) {
    const std::string over = load_error(with_friction(0.3, 0.1), 0.4);
    EXPECT_NE(over.find("|Q| = 0.4 exceeds f = 0.3: the cylinders slide"), std::string::npos) << over;
    const std::string under = load_error(with_friction(0.3, std::nullopt), -0.31);
    EXPECT_NE(under.find("|Q| = 0.31 exceeds f = 0.3: the cylinders slide"), std::string::npos) << under;
    // A scene built by hand is checked too, not only the command line.
    const std::string from_scene = load_error(with_friction(0.3, 0.5), std::nullopt);
    EXPECT_NE(from_scene.find("|Q| = 0.5 exceeds f = 0.3"), std::string::npos) << from_scene;
}

// Physical scenes (physical_scene.hpp): SI keys, Q from P1, roughness as k, t or as T, A
// taken at Hertz's half-width for P2.
const std::string physical_scene_text = R"(
E = 210e9
nu = 0.3
R1 = 0.02
R2 = 0.05
P2 = 1e5
P1 = -1.5e4
friction = 0.3
[cylinder1.tangential]
k = 4e14
t = 1.5e6
[cylinder2.normal]
T = 0.5
A = 2
)";

TEST(PhysicalScene, KeysAndLoads) {
    const scene s = parse_scene(physical_scene_text, source);
    ASSERT_TRUE(s.physical);
    const physical_scene& p = *s.physical;
    EXPECT_EQ(p.E, 210e9);
    EXPECT_EQ(p.nu, 0.3);
    EXPECT_DOUBLE_EQ(p.radius(), 0.02 * 0.05 / 0.07);
    EXPECT_EQ(p.width, width_rule::given_load);
    ASSERT_TRUE(s.Q);
    EXPECT_DOUBLE_EQ(*s.Q, -0.15);
    EXPECT_EQ(p.cylinder1.tangential.k, 4e14);
    EXPECT_EQ(p.cylinder1.tangential.t, 1.5e6);
    EXPECT_FALSE(p.cylinder1.normal.present());
    EXPECT_FALSE(p.cylinder2.tangential.present());
}

TEST(PhysicalScene, DimensionlessTermsAreTakenAtTheHertzWidth) {
    const scene s = parse_scene(physical_scene_text, source);
    const physical_scene& p = *s.physical;
    const double a_H = hertz_half_width(p, p.P2);
    // (3.26) by hand: t = a mu/(8 (1 - nu) T), k = 2 t (A/a)^2.
    const double mu = 210e9 / 2.6;
    const double t = a_H * mu / (8.0 * 0.7 * 0.5);
    EXPECT_NEAR(p.cylinder2.normal.t, t, 1e-12 * t);
    EXPECT_NEAR(p.cylinder2.normal.k, 2.0 * t * 4.0 / (a_H * a_H), 1e-12 * p.cylinder2.normal.k);
    // The surfaces reported before the width search are those at a_H: the T, A written.
    EXPECT_NEAR(s.surfaces.cylinder2.normal.T, 0.5, tol::few_roundings);
    EXPECT_NEAR(s.surfaces.cylinder2.normal.A, 2.0, tol::few_roundings);
    // T and A grow with the width (3.26).
    const roughness wider = roughness_at(p, 2.0 * a_H);
    EXPECT_NEAR(wider.cylinder2.normal.T, 1.0, tol::few_roundings);
    EXPECT_NEAR(wider.cylinder2.normal.A, 4.0, tol::few_roundings);
}

// |P1| = f P2 exactly in decimal, whose quotient P1/P2 rounds one ulp above f: the load is
// f (the limit of the curve), not a refusal naming a Q the user never wrote.
TEST(PhysicalScene, LoadAtTheFrictionLimitSurvivesRounding) {
    const scene s = parse_scene(
        "E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 703382.385\nP1 = 334106.632875\n"
        "friction = 0.475\n",
        source);
    EXPECT_EQ(*s.Q, 0.475);
    EXPECT_EQ(load_of(s, std::nullopt), 0.475);
}

TEST(PhysicalScene, DimensionlessScenesStayDimensionless) {
    const scene s = parse_scene("friction = 0.3\n", source);
    EXPECT_FALSE(s.physical);
}

// A micro-geometry table gives both directions' k, t by (2.11)-(2.14); flat profile and
// linear decay in closed form: k1 = mu0/H, k2 = (lambda0 + 2 mu0)/H, t1 = (lambda0 + 2 mu0) H/6,
// t2 = mu0 H/6.
TEST(PhysicalScene, MicroGeometryGivesBothDirections) {
    const scene s = parse_scene(R"(
E = 210e9
nu = 0.3
R1 = 0.02
R2 = 0.02
P2 = 1e5
friction = 0.3
[cylinder2.micro_geometry]
lambda0 = 1.2e11
mu0 = 8e10
H = 1e-5
l = 1e-4
profile = "flat"
decay = "linear"
)",
                                source);
    const surface_stiffness& c = s.physical->cylinder2;
    EXPECT_NEAR(c.tangential.k, 8e10 / 1e-5, 1e-11 * c.tangential.k);
    EXPECT_NEAR(c.normal.k, 2.8e11 / 1e-5, 1e-11 * c.normal.k);
    EXPECT_NEAR(c.tangential.t, 2.8e11 * 1e-5 / 6.0, 1e-11 * c.tangential.t);
    EXPECT_NEAR(c.normal.t, 8e10 * 1e-5 / 6.0, 1e-11 * c.normal.t);
    EXPECT_FALSE(s.physical->cylinder1.normal.present());
}

TEST(PhysicalScene, MicroGeometryMistakes) {
    const std::string layer =
        "[cylinder1.micro_geometry]\nlambda0 = 1.2e11\nmu0 = 8e10\nH = 1e-5\nl = 1e-4\n"
        "profile = \"flat\"\ndecay = \"linear\"\n";
    const std::string physical = "E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 1e5\nfriction = 0.3\n";
    EXPECT_TRUE(rejects("friction = 0.3\n" + layer, {"'cylinder1.micro_geometry'", "needs a physical scene"}));
    EXPECT_TRUE(rejects(physical + "[cylinder1.normal]\nk = 1e14\nt = 1e6\n" + layer,
                        {"'cylinder1.micro_geometry'", "leave out its 'tangential' and 'normal'"}));
    EXPECT_TRUE(rejects(physical + layer + "Hx = 1\n", {"cylinder1.micro_geometry.Hx"}));
}

// Issue 11: every quantity derived from a physical scene is checked where it is made, and
// the message names the keys it comes from (before: a Hertz width of 0 solved to xi1 = -nan,
// a T of inf reached the solver).
const std::string physical_base = "nu = 0.3\nfriction = 0.3\nQ = 0.1\n";

TEST(PhysicalScene, HertzWidthBeyondDoublePrecisionNamesItsKeys) {
    // a_H = 1.6e-450 m: below every double.
    EXPECT_TRUE(rejects(physical_base + "E = 1e300\nR1 = 1e-300\nR2 = 1e-300\nP2 = 1e-300\n",
                        {"Hertz half-width a_H", "= 0", "check 'E', 'R1', 'R2' and 'P2'"}));
    // a_H = 5e-154 m is a double although 4 (1 - nu) R P underflows: taken, not refused.
    const scene s = parse_scene(physical_base + "E = 1e10\nR1 = 1e-150\nR2 = inf\nP2 = 1e-150\n", source);
    const double a_H = hertz_half_width(*s.physical, 1e-150);
    const double expected = std::sqrt(4.0 * 0.7 / M_PI) * 1e-150 / std::sqrt(1e10 / 2.6);
    EXPECT_NEAR(a_H, expected, 1e-14 * expected);
    // The pressure scale P2/a_H overflows although a_H is a double.
    EXPECT_TRUE(rejects(physical_base + "E = 1e300\nR1 = 1e-300\nR2 = inf\nP2 = 1e300\n",
                        {"the pressure scale P/a_H", "check 'E', 'R1', 'R2' and 'P2'"}));
}

TEST(PhysicalScene, RoughnessBeyondDoublePrecisionNamesItsKeys) {
    const std::string phys = physical_base + "E = 210e9\nR1 = 0.02\nR2 = 0.02\nP2 = 1e5\n";
    // T = a mu/(8 (1 - nu) t) = inf at a_H for t = 1e-305.
    EXPECT_TRUE(rejects(
        phys + "[cylinder1.tangential]\nk = 4e14\nt = 1e-305\n",
        {"'cylinder1.tangential': T = a mu/(8 (1 - nu) t) of (3.26) = inf", "check 'cylinder1.tangential.t' and 'E'"}));
    // A = a sqrt(k/(2 t)) = inf (T = 1.4e306 is still a double).
    EXPECT_TRUE(rejects(phys + "[cylinder2.normal]\nk = 1e308\nt = 1e-300\n",
                        {"'cylinder2.normal': A = a sqrt(k/(2 t)) of (3.26) = inf",
                         "check 'cylinder2.normal.k' and 'cylinder2.normal.t'"}));
    EXPECT_TRUE(rejects(phys + "[cylinder2.normal]\nk = 1.7e308\nt = 1e-5\n",
                        {"'cylinder2.normal': A = a sqrt(k/(2 t)) of (3.26) = inf", "'cylinder2.normal.k'"}));
    // T, A written in a physical scene give t = inf at a_H.
    EXPECT_TRUE(rejects(phys + "[cylinder1.normal]\nT = 1e-305\nA = 0.5\n",
                        {"'cylinder1.normal': t = a mu/(8 (1 - nu) T) of (3.26) = inf", "'cylinder1.normal.T'"}));
    EXPECT_TRUE(rejects(phys + "[cylinder1.normal]\nT = 0.5\nA = 1e300\n",
                        {"'cylinder1.normal': k = 2 t (A/a)^2 of (3.26) = inf", "'cylinder1.normal.A'"}));
    // The roughness at a trial width is checked too (the width search calls roughness_at).
    const scene s = parse_scene(phys + "[cylinder1.tangential]\nk = 4e14\nt = 1e-290\n", source);
    EXPECT_THROW((void)roughness_at(*s.physical, 1e20), input_error);
}

// The one underflow rule (text.hpp) in scene files: a nonzero literal below DBL_MIN is
// refused with its key, line and column; a zero written any way is 0.
TEST(Scene, UnderflowRefusedWhereverWritten) {
    EXPECT_TRUE(
        rejects("friction = 1e-400\n",
                {"scene.toml:1:12:", "'friction' = 1e-400 is below 2.2250738585072014e-308", "it would be read as 0"}));
    EXPECT_TRUE(rejects("friction = 0.3\nQ = -2.5e-310\n",
                        {"scene.toml:2:5:", "'Q' = -2.5e-310 is below", "the subnormal -2.5e-310, with digits lost"}));
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1]\ntangential = { T = 0.5, A = 0.000_000_1e-302 }\n",
                        {"'cylinder1.tangential.A' = 0.000_000_1e-302 is below"}));
    // A key holding non-ASCII text before the value on its line: toml++ counts columns in
    // code points, the literal is still found.
    EXPECT_TRUE(rejects("friction = 0.3\n[cylinder1]\ntangential = { \"\xc3\xa9\xc3\xa9\" = 0, T = 1e-999 }\n",
                        {"'cylinder1.tangential.T' = 1e-999 is below"}));
    for (const char* zero : {"0.0", "-0.0", "0e-400", "0.000e5", "+0.0"}) {
        const scene s = parse_scene(std::string("friction = 0.3\nQ = ") + zero + "\n", source);
        EXPECT_EQ(*s.Q, 0.0) << zero;
    }
    // The smallest normal double itself is a number.
    EXPECT_EQ(*parse_scene("friction = 0.3\nQ = 2.2250738585072014e-308\n", source).Q, 2.2250738585072014e-308);
}

// Friction outside the range validation/test_stiff.cpp shows the solver resolves.
TEST(Scene, FrictionWithinTheValidatedRange) {
    EXPECT_TRUE(rejects("friction = 1e-13\n", {"'friction' = 1e-13 is outside [1e-12, 1e+12]"}));
    EXPECT_TRUE(rejects("friction = 1.79e308\n", {"'friction' = 1.79e+308 is outside"}));
    EXPECT_EQ(parse_scene("friction = 1e-12\n", source).friction, 1e-12);
    EXPECT_EQ(parse_scene("friction = 1e12\n", source).friction, 1e12);
}

// A 1 MB key or value is shown cut, not whole.
TEST(Scene, LongEchoesAreCut) {
    const std::string key(1000000, 'k');
    try {
        (void)parse_scene("friction = 0.3\n" + key + " = 1\n", source);
        ADD_FAILURE() << "accepted";
    } catch (const input_error& e) {
        const std::string message = e.what();
        EXPECT_LT(message.size(), 300u);
        EXPECT_NE(message.find("unknown key '" + std::string(60, 'k') + "...'"), std::string::npos) << message;
    }
    EXPECT_TRUE(rejects("friction = 0.3\n[solver]\nmethod = \"" + std::string(5000, 'm') + "\"\n", {"mmm..."}));
    // A dotted key of 50 long parts (fuzz_scene's finding): the path shown is cut too.
    std::string dotted;
    for (int i = 0; i < 50; ++i) dotted += (i ? "." : "") + std::string(60, 'a' + i % 26);
    try {
        (void)parse_scene("friction = 0.3\n" + dotted + " = 1e-400\n", source);
        ADD_FAILURE() << "accepted";
    } catch (const input_error& e) {
        EXPECT_LT(std::string(e.what()).size(), 500u) << e.what();
    }
}

// read_scene names the files read: an output must not overwrite one of them.
TEST(ReadScene, RecordsTheFilesRead) {
    const std::string path = ::testing::TempDir() + "roughroll_files_read.toml";
    std::ofstream(path) << "friction = 0.3\n";
    EXPECT_EQ(read_scene(path).files, std::vector<std::string>{path});
    std::filesystem::remove(path);
}

// docs/formulation.md 8(a): a material per cylinder gives C and Dundurs' beta_D; equal materials
// written per cylinder are the one-material scene (C = 2 (1 - nu)/mu, beta_D = 0).
TEST(PhysicalScene, MaterialPerCylinder) {
    const std::string pair = R"(R1 = 0.05
R2 = 0.05
P2 = 1e5
friction = 0.05
Q = -0.03
coupling = "johnson"
[cylinder1]
shear_modulus = 23e9
poisson = 0.31
[cylinder2]
shear_modulus = 82e9
poisson = 0.28
)";
    const scene s = parse_scene(pair, source);
    ASSERT_TRUE(s.physical && s.physical->materials);
    const double C = 0.69 / 23e9 + 0.72 / 82e9;
    EXPECT_DOUBLE_EQ(compliance(*s.physical), C);
    // The pair of the issue: 0.143834 (validation/test_dissimilar.cpp, from the same definition).
    EXPECT_NEAR(s.materials.beta_d, 0.143834, 5e-7);
    EXPECT_DOUBLE_EQ(s.materials.beta_d, (0.38 / 23e9 - 0.44 / 82e9) / (2.0 * C));
    EXPECT_EQ(s.materials.coupling, coupling_level::johnson);
    // Exchanged rollers: the opposite sign (8(h)).
    std::string exchanged = pair;
    exchanged.replace(exchanged.find("23e9"), 4, "82e9");
    exchanged.replace(exchanged.find("0.31"), 4, "0.28");
    exchanged.replace(exchanged.rfind("82e9"), 4, "23e9");
    exchanged.replace(exchanged.rfind("0.28"), 4, "0.31");
    EXPECT_DOUBLE_EQ(parse_scene(exchanged, source).materials.beta_d, -s.materials.beta_d);
    // Equal materials per cylinder: beta_D = 0 exactly, and the one-material scene's width and T.
    const std::string same = R"(R1 = 0.05
R2 = 0.05
P2 = 1e5
friction = 0.3
Q = 0.1
[cylinder1]
shear_modulus = 80e9
poisson = 0.3
[cylinder1.tangential]
k = 4e14
t = 1.5e6
[cylinder2]
shear_modulus = 80e9
poisson = 0.3
)";
    const scene a = parse_scene(same, source);
    std::string one_text = R"(E = 208e9
nu = 0.3
R1 = 0.05
R2 = 0.05
P2 = 1e5
friction = 0.3
Q = 0.1
[cylinder1.tangential]
k = 4e14
t = 1.5e6
)";
    const scene b = parse_scene(one_text, source);
    EXPECT_EQ(a.materials.beta_d, 0.0);
    EXPECT_NEAR(compliance(*a.physical), compliance(*b.physical), 1e-15 * compliance(*b.physical));
    EXPECT_NEAR(hertz_half_width(*a.physical, 1e5), hertz_half_width(*b.physical, 1e5),
                1e-15 * hertz_half_width(*b.physical, 1e5));
    EXPECT_NEAR(a.surfaces.cylinder1.tangential.T, b.surfaces.cylinder1.tangential.T,
                1e-14 * b.surfaces.cylinder1.tangential.T);
    EXPECT_EQ(b.materials.beta_d, 0.0);
}

TEST(Scene, BetaAndCoupling) {
    const scene s = parse_scene("friction = 0.05\nQ = -0.03\nbeta_d = -0.2\ncoupling = \"full\"\n", source);
    EXPECT_EQ(s.materials.beta_d, -0.2);
    EXPECT_EQ(s.materials.coupling, coupling_level::full);
    const scene d = parse_scene("friction = 0.05\n", source);
    EXPECT_EQ(d.materials.beta_d, 0.0);
    EXPECT_EQ(d.materials.coupling, coupling_level::johnson);
    // The bound of 8(a): just inside is accepted, 3/4 itself and beyond refused.
    EXPECT_NO_THROW(parse_scene("friction = 0.05\nbeta_d = 0.7499\n", source));
    EXPECT_THROW(parse_scene("friction = 0.05\nbeta_d = -0.75\n", source), input_error);
    EXPECT_THROW(parse_scene("friction = 0.05\ncoupling = \"weak\"\n", source), input_error);
}

// A load given as Q/f (issue 25): the key Q_over_f, Q = (Q/f) f, and the ratio kept under
// another friction; one load only; |Q/f| <= 1 and finite.
TEST(LoadRatio, SceneKeyGivesQ) {
    const scene s = parse_scene("friction = 0.3\nQ_over_f = 0.5\n", source);
    ASSERT_TRUE(s.Q && s.Q_over_f);
    EXPECT_EQ(*s.Q, 0.15);
    EXPECT_EQ(*s.Q_over_f, 0.5);
    EXPECT_EQ(load_of(s, std::nullopt), 0.15);
    const scene edge = parse_scene("friction = 0.3\nQ_over_f = -1\n", source);
    EXPECT_EQ(load_of(edge, std::nullopt), -0.3);
}

TEST(LoadRatio, FollowsTheFrictionOverride) {
    scene s = parse_scene("friction = 0.3\nQ_over_f = 0.5\n", source);
    override_friction(s, 0.2);
    EXPECT_EQ(load_of(s, std::nullopt), 0.1);
    scene q = parse_scene("friction = 0.3\nQ = 0.15\n", source);  // a Q stays Q
    override_friction(q, 0.2);
    EXPECT_EQ(load_of(q, std::nullopt), 0.15);
}

TEST(LoadRatio, OneLoadOnly) {
    EXPECT_TRUE(rejects("friction = 0.3\nQ = 0.1\nQ_over_f = 0.5\n", {"'Q' or 'Q_over_f', not both"}));
    EXPECT_TRUE(
        rejects("E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 1e5\nP1 = 1e4\nQ_over_f = 0.5\n"
                "friction = 0.3\n",
                {"'Q_over_f' or 'P1', not both"}));
}

TEST(LoadRatio, RangeAndFiniteness) {
    for (const char* bad : {"1.5", "-1.0000001", "nan", "inf", "-inf"})
        EXPECT_TRUE(rejects(std::string("friction = 0.3\nQ_over_f = ") + bad + "\n", {"'Q_over_f' must"})) << bad;
    EXPECT_TRUE(rejects("friction = 0.3\nQ_over_f = 2\n", {"|Q/f| = 2 exceeds 1: the cylinders slide"}));
    EXPECT_TRUE(rejects("friction = 0.3\nQ_over_f = \"half\"\n", {"Q_over_f"}));
}

// The largest double below 1 is not gross sliding: Q stays below f (rounding is monotone).
TEST(LoadRatio, JustBelowGrossSliding) {
    const double q = std::nextafter(1.0, 0.0);
    for (const double f : {0.3, 0.25, 0.49999999999999994, 1e-12, 7.0, 1e12}) {
        const scene s = with_friction(f, std::nullopt);
        const double Q = load_of(s, load_given(load_kind::Q_over_f, q));
        EXPECT_LT(Q, f) << f;
        EXPECT_LT(Q / f, 1.0) << f;
    }
}

TEST(LoadRatio, Overrides) {
    const scene s = with_friction(0.3, 0.1);
    EXPECT_EQ(load_of(s, load_given(load_kind::Q_over_f, 0.5)), 0.15);
    EXPECT_EQ(load_of(s, load_given(load_kind::Q_over_f, -1.0)), -0.3);
    const auto error = [&s](double q) {
        try {
            (void)load_of(s, load_given(load_kind::Q_over_f, q));
        } catch (const input_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error(1.5), "Q_over_f must lie in [-1, 1], but |Q/f| = 1.5 exceeds 1: the cylinders slide");
    EXPECT_EQ(error(std::numeric_limits<double>::infinity()), "Q_over_f must be finite (got inf)");
}

// P1 (N/m) over a physical scene's load: Q = P1/P2; refused for a dimensionless scene, beyond
// f P2, and at the Hertz width.
TEST(LoadP1, Overrides) {
    const scene s = parse_scene(physical_scene_text, source);
    EXPECT_EQ(load_of(s, load_given(load_kind::P1, 1e4)), 0.1);
    EXPECT_EQ(load_of(s, load_given(load_kind::P1, -3e4)), -0.3);
    const auto error = [](const scene& sc, double P1) {
        try {
            (void)load_of(sc, load_given(load_kind::P1, P1));
        } catch (const input_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error(s, 30001.0).find("P1 must satisfy |P1| <= f P2"), std::string::npos);
    EXPECT_NE(error(s, std::nan("")).find("P1 must be finite"), std::string::npos);
    EXPECT_NE(error(with_friction(0.3, 0.1), 1e4).find("P1 (N/m) needs a physical scene"), std::string::npos);
    const scene hertz = parse_scene(
        "E = 210e9\nnu = 0.3\nR1 = 0.02\nR2 = 0.02\nP2 = 1e5\nQ = 0.1\n"
        "contact_width = \"hertz\"\nfriction = 0.3\n",
        source);
    EXPECT_NE(error(hertz, 1e4).find("given-load"), std::string::npos);
}

}  // namespace
}  // namespace roughroll
