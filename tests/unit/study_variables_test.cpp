// Participant variables given as NAME=VALUE: checked against the protocol's declarations
// before any trial, every problem at once and each naming the variable and what is allowed;
// accepted values kept in one canonical text.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "study/participant_variables.h"

namespace monoplane::study {
namespace {

// A declaration with the optional parts left at their defaults.
ParticipantVariable declared(std::string name, VariableType type, std::optional<double> min = {},
                             std::optional<double> max = {}) {
    ParticipantVariable variable;
    variable.name = std::move(name);
    variable.type = type;
    variable.min = min;
    variable.max = max;
    return variable;
}

const std::vector<ParticipantVariable> kDeclarations = {
    {"age", VariableType::Integer, 18.0, 99.0, {}, true, "Age in years"},
    {"vision",
     VariableType::Choice,
     std::nullopt,
     std::nullopt,
     {"normal", "corrected", "other"},
     true,
     ""},
    {"ipd_mm", VariableType::Number, 50.0, std::nullopt, {}, false, "Interpupillary distance"},
    declared("remark", VariableType::Text),
};

TEST(StudyVariables, ValuesComeBackInDeclarationOrderInCanonicalText) {
    const Result<std::vector<VariableValue>> values = check_variables(
        kDeclarations,
        {"remark=wears contact lenses", "vision=corrected", "ipd_mm=63.50", "age=042"});
    ASSERT_TRUE(values.ok()) << values.error().message;
    EXPECT_EQ(*values, (std::vector<VariableValue>{
                           {"age", VariableType::Integer, "42"},
                           {"vision", VariableType::Choice, "corrected"},
                           {"ipd_mm", VariableType::Number, "63.5"},
                           {"remark", VariableType::Text, "wears contact lenses"},
                       }));
}

TEST(StudyVariables, OptionalVariablesMayBeLeftOut) {
    const Result<std::vector<VariableValue>> values =
        check_variables(kDeclarations, {"age=18", "vision=normal"});
    ASSERT_TRUE(values.ok()) << values.error().message;
    EXPECT_EQ(*values, (std::vector<VariableValue>{{"age", VariableType::Integer, "18"},
                                                   {"vision", VariableType::Choice, "normal"}}));
    const Result<std::vector<VariableValue>> none = check_variables({}, {});
    ASSERT_TRUE(none.ok());
    EXPECT_TRUE(none->empty());
}

TEST(StudyVariables, AMissingRequiredVariableSaysWhatToGive) {
    const Result<std::vector<VariableValue>> values = check_variables(kDeclarations, {});
    ASSERT_FALSE(values.ok());
    EXPECT_EQ(
        values.error().message,
        "variable 'age' is required (Age in years): give variable age=VALUE, an integer from 18 "
        "to 99\n"
        "variable 'vision' is required: give variable vision=VALUE, one of normal, corrected, "
        "other");
}

TEST(StudyVariables, EveryProblemIsReportedAtOnce) {
    const Result<std::vector<VariableValue>> values = check_variables(
        kDeclarations, {"age=17", "vision=blue", "agee=3", "ipd_mm=63,5", "remark", "age=40"});
    ASSERT_FALSE(values.ok());
    EXPECT_EQ(values.error().message,
              "variable age=17: out of range; age must be an integer from 18 to 99\n"
              "variable vision=blue: not one of normal, corrected, other\n"
              "variable agee=3: unknown variable 'agee'; did you mean 'age'?\n"
              "variable ipd_mm=63,5: not a number (use '.' as the decimal point); ipd_mm must be a "
              "number of at least 50\n"
              "variable remark: expected NAME=VALUE (the protocol declares: age, vision, ipd_mm, "
              "remark)\n"
              "variable age=40: variable 'age' is given twice; give each variable once");
}

TEST(StudyVariables, UnknownNamesListTheDeclaredOnes) {
    const Result<std::vector<VariableValue>> far =
        check_variables(kDeclarations, {"age=30", "vision=normal", "handedness=left"});
    ASSERT_FALSE(far.ok());
    EXPECT_EQ(
        far.error().message,
        "variable handedness=left: unknown variable 'handedness' (the protocol declares: age, "
        "vision, ipd_mm, remark)");
    const Result<std::vector<VariableValue>> none = check_variables({}, {"age=30"});
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().message,
              "variable age=30: unknown variable 'age' (the protocol declares no variables)");
}

TEST(StudyVariables, IntegersArePlainDecimal) {
    const ParticipantVariable& age = kDeclarations[0];
    EXPECT_EQ(check_variable_value(age, "42").value(), "42");
    EXPECT_EQ(check_variable_value(age, "99").value(), "99");
    EXPECT_EQ(check_variable_value(age, "018").value(), "18");
    for (const char* bad :
         {"4.0", "+42", " 42", "42 ", "4e1", "forty", "", "0x2a", "42y", "99999999999999999999"}) {
        const Result<std::string> value = check_variable_value(age, bad);
        ASSERT_FALSE(value.ok()) << bad;
        EXPECT_EQ(value.error().message, "variable age=" + std::string(bad) +
                                             ": not an integer; age must be an integer from 18 "
                                             "to 99");
    }
    EXPECT_EQ(check_variable_value(age, "100").error().message,
              "variable age=100: out of range; age must be an integer from 18 to 99");
    const ParticipantVariable open = declared("count", VariableType::Integer);
    EXPECT_EQ(check_variable_value(open, "-0").value(), "0");
    EXPECT_EQ(check_variable_value(open, "-7").value(), "-7");
    const ParticipantVariable low = declared("trials", VariableType::Integer, 1.0);
    EXPECT_EQ(check_variable_value(low, "0").error().message,
              "variable trials=0: out of range; trials must be an integer of at least 1");
}

TEST(StudyVariables, NumbersReadAndWriteWithAPointInAnyLocale) {
    const ParticipantVariable x = declared("x", VariableType::Number, std::nullopt, 10.0);
    EXPECT_EQ(check_variable_value(x, "1.50").value(), "1.5");
    EXPECT_EQ(check_variable_value(x, "0.1").value(), "0.1");
    EXPECT_EQ(check_variable_value(x, "3").value(), "3");
    EXPECT_EQ(check_variable_value(x, "-0.0").value(), "0");
    EXPECT_EQ(check_variable_value(x, "2.5e-3").value(), "0.0025");
    EXPECT_EQ(check_variable_value(x, "10").value(), "10");
    for (const char* bad : {"nan", "inf", "", "1.5 ", "+1", "1..5", "abc"}) {
        const Result<std::string> value = check_variable_value(x, bad);
        ASSERT_FALSE(value.ok()) << bad;
        EXPECT_EQ(value.error().message, "variable x=" + std::string(bad) +
                                             ": not a number; x must be a number of at most 10");
    }
    EXPECT_EQ(check_variable_value(x, "10.5").error().message,
              "variable x=10.5: out of range; x must be a number of at most 10");
}

TEST(StudyVariables, ChoicesAreExactWithAHint) {
    const ParticipantVariable& vision = kDeclarations[1];
    EXPECT_EQ(check_variable_value(vision, "other").value(), "other");
    EXPECT_EQ(
        check_variable_value(vision, "Normal").error().message,
        "variable vision=Normal: not one of normal, corrected, other; did you mean 'normal'?");
    EXPECT_EQ(check_variable_value(vision, "").error().message,
              "variable vision=: not one of normal, corrected, other");
}

TEST(StudyVariables, TextIsOneLineOfAtMostAThousandCharacters) {
    const ParticipantVariable& remark = kDeclarations[3];
    EXPECT_EQ(check_variable_value(remark, "=SUM(A1) stays as typed").value(),
              "=SUM(A1) stays as typed");
    EXPECT_EQ(check_variable_value(remark, "tab\tis fine").value(), "tab\tis fine");
    EXPECT_EQ(check_variable_value(remark, "Brille, sehr gut: \xc3\xbc").value(),
              "Brille, sehr gut: \xc3\xbc");
    // 1000 characters of two bytes each are still 1000 characters.
    std::string umlauts;
    for (int i = 0; i < 1000; ++i) umlauts += "\xc3\xbc";
    EXPECT_TRUE(check_variable_value(remark, umlauts).ok());
    const std::string allowed =
        "; remark must be a text of 1 to 1000 characters without control characters";
    EXPECT_EQ(check_variable_value(remark, umlauts + "x").error().message,
              "variable remark=" + umlauts + "x: 1001 characters is too long" + allowed);
    EXPECT_EQ(check_variable_value(remark, "").error().message,
              "variable remark=: empty" + allowed);
    EXPECT_EQ(check_variable_value(remark, "two\nlines").error().message,
              "variable remark=two\nlines: has a control character (a line break?)" + allowed);
    EXPECT_EQ(check_variable_value(remark, "bad \xc3").error().message,
              "variable remark=bad \xc3: not valid UTF-8 text" + allowed);
}

TEST(StudyVariables, AValueWithAnEqualsSignKeepsIt) {
    const Result<std::vector<VariableValue>> values =
        check_variables(kDeclarations, {"age=30", "vision=normal", "remark=a=b"});
    ASSERT_TRUE(values.ok()) << values.error().message;
    EXPECT_EQ(values->back(), (VariableValue{"remark", VariableType::Text, "a=b"}));
}

}  // namespace
}  // namespace monoplane::study
