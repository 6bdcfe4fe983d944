// summary.json keeps the participant variables' types (analysis/report/study_day_section.h):
// integer and number variables are JSON numbers, every digit as recorded; choice and text stay
// strings, also when they look like numbers; a value not given is null. From a CSV export,
// which does not record types, a variable whose every value is a number is one.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/report/study_day_section.h"

namespace monoplane::analysis::report {
namespace {

SessionRow session(const std::string& code, const std::string& source,
                   std::vector<std::pair<std::string, std::string>> variables) {
    SessionRow s;
    s.source = source;
    s.participant = code;
    s.variables = std::move(variables);
    return s;
}

// The "participant_details" of summary.json for `data`, parsed.
nlohmann::json details(const Dataset& data) {
    JsonWriter json(JsonFormat{.indented = true});
    json.begin_object();
    study_day_json(json, study_day(data));
    json.end_object();
    return nlohmann::json::parse(json.str()).at("participant_details");
}

TEST(VariableTypes, NumbersFromADatabaseAreJsonNumbers) {
    Dataset data;
    // As a database records them: the protocol's types with each value.
    SessionRow p1 = session("P1", "a.sqlite",
                            {{"age", "34"},
                             {"height_m", "1.75"},
                             {"vision", "normal"},
                             {"room", "12"},
                             {"id", "12345678901234567890"}});
    SessionRow p2 = session("P2", "a.sqlite", {{"age", "51"}, {"height_m", "2"}, {"room", "B"}});
    for (SessionRow* s : {&p1, &p2}) {
        s->variable_is_number = {
            {"age", true}, {"height_m", true}, {"vision", false}, {"room", false}, {"id", true}};
    }
    data.sessions = {p1, p2};
    const nlohmann::json d = details(data);
    ASSERT_EQ(d.size(), 2u);
    const nlohmann::json& v1 = d[0].at("variables");
    EXPECT_TRUE(v1.at("age").is_number_integer());
    EXPECT_EQ(v1.at("age"), 34);
    EXPECT_TRUE(v1.at("height_m").is_number_float());
    EXPECT_EQ(v1.at("height_m"), 1.75);
    EXPECT_EQ(v1.at("vision"), "normal");
    EXPECT_EQ(v1.at("room"), "12");  // a text variable that looks like a number stays text
    EXPECT_TRUE(v1.at("id").is_number_unsigned());
    EXPECT_EQ(v1.at("id").get<std::uint64_t>(), 12345678901234567890ull);  // every digit
    const nlohmann::json& v2 = d[1].at("variables");
    EXPECT_EQ(v2.at("age"), 51);
    EXPECT_TRUE(v2.at("height_m").is_number());
    EXPECT_EQ(v2.at("height_m"), 2);
    EXPECT_TRUE(v2.at("vision").is_null());  // not given
    EXPECT_TRUE(v2.at("id").is_null());
    EXPECT_EQ(v2.at("room"), "B");
}

TEST(VariableTypes, TheWrittenTextIsTheRecordedNumber) {
    Dataset data;
    SessionRow p1 = session("P1", "a.sqlite", {{"age", "34"}, {"height_m", "1.75"}});
    p1.variable_is_number = {{"age", true}, {"height_m", true}};
    data.sessions = {p1};
    JsonWriter json(JsonFormat{.indented = true, .line_levels = 1});
    json.begin_object();
    study_day_json(json, study_day(data));
    json.end_object();
    EXPECT_NE(json.str().find("\"variables\": {\"age\": 34, \"height_m\": 1.75}"),
              std::string::npos)
        << json.str();
}

TEST(VariableTypes, FromACsvExportAColumnOfNumbersIsANumber) {
    Dataset data;
    // As read from an export: no types recorded.
    data.sessions = {session("e1", "day.csv", {{"age", "34"}, {"code", "007"}, {"note", "=1+2"}}),
                     session("e2", "day.csv", {{"age", "29"}, {"code", "12"}})};
    const nlohmann::json d = details(data);
    EXPECT_EQ(d[0].at("variables").at("age"), 34);
    EXPECT_EQ(d[1].at("variables").at("age"), 29);
    // "007" is no number as JSON or CSV readers write one: the whole column stays text.
    EXPECT_EQ(d[0].at("variables").at("code"), "007");
    EXPECT_EQ(d[1].at("variables").at("code"), "12");
    EXPECT_EQ(d[0].at("variables").at("note"), "=1+2");
    EXPECT_TRUE(d[1].at("variables").at("note").is_null());
}

TEST(VariableTypes, ADatabasesTextTypeWinsOverACsvsNumbers) {
    Dataset data;
    SessionRow a = session("a1", "a.sqlite", {{"room", "12"}});
    a.variable_is_number = {{"room", false}};
    data.sessions = {a, session("c1", "c.csv", {{"room", "14"}})};
    const nlohmann::json d = details(data);
    EXPECT_EQ(d[0].at("variables").at("room"), "12");
    EXPECT_EQ(d[1].at("variables").at("room"), "14");
}

}  // namespace
}  // namespace monoplane::analysis::report
