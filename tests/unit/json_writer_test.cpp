// The project's one JSON writer (common/json_writer.h): its escaping rule, its number text and its
// three layouts (one line; indented; the study export's one record per line).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "common/json_writer.h"

namespace monoplane {
namespace {

TEST(JsonWriter, QuotesAndBackslashesAreEscaped) {
    EXPECT_EQ(json_quoted("plain"), "\"plain\"");
    EXPECT_EQ(json_quoted(""), "\"\"");
    EXPECT_EQ(json_quoted("a\"b\\c"), "\"a\\\"b\\\\c\"");
    EXPECT_EQ(json_quoted("/slash/"), "\"/slash/\"");  // JSON allows '/' unescaped
}

TEST(JsonWriter, ControlCharactersAreEscaped) {
    EXPECT_EQ(json_quoted("l1\nl2\tx\r"), "\"l1\\nl2\\tx\\r\"");
    EXPECT_EQ(json_quoted(std::string("\x01", 1)), "\"\\u0001\"");
    EXPECT_EQ(json_quoted(std::string("a\0b", 3)), "\"a\\u0000b\"");
    EXPECT_EQ(json_quoted("\b\f"), "\"\\u0008\\u000c\"");
    EXPECT_EQ(json_quoted("\x1f"), "\"\\u001f\"");
    EXPECT_EQ(json_quoted("\x7f"), "\"\x7f\"");  // DEL is no control character to JSON
}

TEST(JsonWriter, NonAsciiPassesThroughAsTyped) {
    EXPECT_EQ(json_quoted("caf\xc3\xa9"), "\"caf\xc3\xa9\"");
    EXPECT_EQ(json_quoted("\xe2\x82\xac \xf0\x9f\x91\x8d"), "\"\xe2\x82\xac \xf0\x9f\x91\x8d\"");
}

TEST(JsonWriter, KeysAreEscapedLikeValues) {
    JsonWriter json;
    json.begin_object().value("a\"b\n", "\xc3\xa9\t").end_object();
    EXPECT_EQ(json.str(), "{\"a\\\"b\\n\":\"\xc3\xa9\\t\"}");
}

TEST(JsonWriter, OneLineHasNoSpaces) {
    JsonWriter json;
    json.begin_object()
        .value("n", 0.1)
        .value("i", 3)
        .value("big", std::int64_t{-9'000'000'000})
        .value("u", std::uint64_t{18'000'000'000'000'000'000u})
        .value("yes", true)
        .null("none")
        .value("inf", std::numeric_limits<double>::infinity())
        .begin_array("list")
        .value("", 1.5)
        .value("", "x")
        .end_array()
        .begin_array("empty")
        .end_array()
        .end_object();
    EXPECT_EQ(json.str(),
              "{\"n\":0.1,\"i\":3,\"big\":-9000000000,\"u\":18000000000000000000,\"yes\":true,"
              "\"none\":null,\"inf\":null,\"list\":[1.5,\"x\"],\"empty\":[]}");
}

TEST(JsonWriter, NumbersKeepTheRequestedDigits) {
    EXPECT_EQ(json_number_text(0.1), "0.1");
    EXPECT_EQ(json_number_text(-0.0), "0");
    EXPECT_EQ(json_number_text(1e-12), "1e-12");
    EXPECT_EQ(json_number_text(2.0 / 3.0, 4), "0.6667");
    EXPECT_EQ(json_number_text(2.0 / 3.0), "0.6666666666666666");
    JsonWriter ten;  // the default: ten significant digits
    ten.begin_array().value("", 2.0 / 3.0).end_array();
    EXPECT_EQ(ten.str(), "[0.6666666667]");
}

TEST(JsonWriter, IndentedPutsEveryMemberOnALine) {
    JsonWriter json({.indented = true});
    json.begin_object()
        .value("a", 1)
        .begin_array("b")
        .value("", 2)
        .begin_object()
        .value("c", "d")
        .end_object()
        .end_array()
        .begin_object("e")
        .end_object()
        .end_object();
    EXPECT_EQ(json.str(),
              "{\n  \"a\": 1,\n  \"b\": [\n    2,\n    {\n      \"c\": \"d\"\n    }\n  ],\n"
              "  \"e\": {}\n}\n");
}

// The study export's layout: one record per line, ", " and ": " within it, nested lists inline.
TEST(JsonWriter, LineLevelsPutDeeperMembersOnOneLine) {
    JsonWriter json({.indented = true, .line_levels = 1});
    json.begin_array();
    json.begin_object().value("a", 1).null("b").begin_array("c").end_array().end_object();
    json.begin_object()
        .value("a", 2)
        .value("b", "x")
        .begin_array("c")
        .begin_object()
        .value("d", true)
        .value("e", 0.5)
        .end_object()
        .value("", 3)
        .end_array()
        .end_object();
    json.end_array();
    EXPECT_EQ(json.str(),
              "[\n  {\"a\": 1, \"b\": null, \"c\": []},\n"
              "  {\"a\": 2, \"b\": \"x\", \"c\": [{\"d\": true, \"e\": 0.5}, 3]}\n]\n");
    JsonWriter empty({.indented = true, .line_levels = 1});
    empty.begin_array().end_array();
    EXPECT_EQ(empty.str(), "[]\n");
}

TEST(JsonWriter, FormattedNumbersKeepTheirDigits) {
    JsonWriter json;
    json.begin_object()
        .formatted_number("s", "9223372036.854775807")
        .formatted_number("zero", "0.0")
        .formatted_number("e", "-1e+20")
        .end_object();
    EXPECT_EQ(json.str(), "{\"s\":9223372036.854775807,\"zero\":0.0,\"e\":-1e+20}");
}

TEST(JsonWriter, TakeStreamsTheDocumentInParts) {
    JsonWriter json({.indented = true, .line_levels = 1});
    json.begin_array();
    json.begin_object().value("a", 1).end_object();
    EXPECT_EQ(json.take(), "[\n  {\"a\": 1}");
    EXPECT_EQ(json.str(), "");
    json.begin_object().value("a", 2).end_object();
    EXPECT_EQ(json.take(), ",\n  {\"a\": 2}");
    json.end_array();
    EXPECT_EQ(json.take(), "\n]\n");
}

TEST(JsonWriter, JsonNumbersAreRecognised) {
    for (const char* number : {"0", "-0.5", "1e+20", "34", "1E5", "-12.25e-3"})
        EXPECT_TRUE(is_json_number(number)) << number;
    for (const char* text : {"5.", ".5", "007", "+1", "1e", "inf", "nan", "", "-", "1 ", "0x1"})
        EXPECT_FALSE(is_json_number(text)) << text;
}

}  // namespace
}  // namespace monoplane
