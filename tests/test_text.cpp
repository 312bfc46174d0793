// SPDX-License-Identifier: GPL-3.0-or-later
// base/text: numbers to significant digits, messages as one line of valid UTF-8, cut echoes, and
// the one rule by which a number written as text is read (issue 11).
#include "roughroll/base/text.hpp"

#include <cfloat>
#include <limits>
#include <string>

#include <gtest/gtest.h>

namespace roughroll {
namespace {

// printf's %.<digits>g: the bounds in the ladder's messages (3), the traction plot's labels (2-4), the
// progress lines (3, 4) and `roughroll roughness`'s table (12) write their numbers so.
TEST(Significant, RoundsToTheDigitsAskedFor) {
    EXPECT_EQ(significant(0.000123456, 3), "0.000123");
    EXPECT_EQ(significant(1234567.0, 3), "1.23e+06");
    EXPECT_EQ(significant(2.0 / 3.0, 12), "0.666666666667");
    EXPECT_EQ(significant(0.05, 2), "0.05");
    EXPECT_EQ(significant(-0.0, 3), "-0");
    EXPECT_EQ(significant(-std::numeric_limits<double>::infinity(), 3), "-inf");
    // More digits than a fixed buffer of 32 would hold.
    EXPECT_EQ(significant(0.1, 40), "0.1000000000000000055511151231257827021182");
    EXPECT_EQ(significant(-DBL_MAX, 30), "-1.79769313486231570814527423732e+308");
}

TEST(OneLine, ControlCharactersAndInvalidUtf8AreEscaped) {
    EXPECT_EQ(one_line("a\nb\tc\x7f"), "a\\x0ab\\x09c\\x7f");
    EXPECT_EQ(one_line("bad\xffname"), "bad\\xffname");
    // Valid sequences of 2, 3 and 4 bytes stay as they are.
    EXPECT_EQ(one_line("\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"), "\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80");
    // Overlong forms, a surrogate, a code point above U+10FFFF, a lone continuation byte and
    // a sequence cut short are not UTF-8: each byte escaped.
    EXPECT_EQ(one_line("\xc0\x80"), "\\xc0\\x80");
    EXPECT_EQ(one_line("\xe0\x80\xaf"), "\\xe0\\x80\\xaf");
    EXPECT_EQ(one_line("\xed\xa0\x80"), "\\xed\\xa0\\x80");
    EXPECT_EQ(one_line("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");
    EXPECT_EQ(one_line("\x80"), "\\x80");
    EXPECT_EQ(one_line("\xe2\x82"), "\\xe2\\x82");
}

TEST(Echo, LongTextIsCutAtACharacterBoundary) {
    EXPECT_EQ(echo(std::string(60, 'k')), std::string(60, 'k'));
    EXPECT_EQ(echo(std::string(1000000, 'k')), std::string(60, 'k') + "...");
    // A two-byte character across the cut is left out whole, not split.
    const std::string text = std::string(59, 'a') + "\xc3\xa9" + "zzz";
    EXPECT_EQ(echo(text), std::string(59, 'a') + "...");
    EXPECT_EQ(echo("a\nb", 2), "a\\x0a...");  // the cut counts input bytes
}

TEST(ParseDouble, TheOneNumberRule) {
    std::string problem;
    EXPECT_EQ(parse_double("0.3", problem), 0.3);
    EXPECT_EQ(parse_double("-1e-300", problem), -1e-300);
    EXPECT_EQ(parse_double("2.2250738585072014e-308", problem), DBL_MIN);
    EXPECT_EQ(parse_double("0e-999", problem), 0.0);
    EXPECT_TRUE(problem.empty());
    for (const char* not_a_number : {"", "1.5x", " 1", "+1", "abc", "0x1p3", "1,5"}) {
        EXPECT_FALSE(parse_double(not_a_number, problem)) << not_a_number;
        EXPECT_TRUE(problem.empty()) << not_a_number;
    }
    EXPECT_FALSE(parse_double("1e-400", problem));
    EXPECT_EQ(problem, "1e-400 is below 2.2250738585072014e-308, the smallest normal double: it would be read as 0");
    EXPECT_FALSE(parse_double("-1e-310", problem));
    EXPECT_EQ(problem,
              "-1e-310 is below 2.2250738585072014e-308, the smallest normal double: it would be read as "
              "the subnormal -1e-310, with digits lost");
    EXPECT_FALSE(parse_double("1e400", problem));
    EXPECT_EQ(problem, "1e400 is beyond 1.7976931348623157e+308, the largest double");
}

TEST(UnderflowProblem, ZeroWrittenAsZeroIsNotAnUnderflow) {
    EXPECT_EQ(underflow_problem("0.000", 0.0), "");
    EXPECT_EQ(underflow_problem("-0e-400", -0.0), "");
    EXPECT_EQ(underflow_problem("0_0.0", 0.0), "");
    EXPECT_NE(underflow_problem("0.001e-400", 0.0), "");
    EXPECT_EQ(underflow_problem("1e-300", 1e-300), "");  // normal: not this rule's
}

}  // namespace
}  // namespace roughroll
