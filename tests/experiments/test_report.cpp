// The benchmarks' report writer (experiments/report.hpp): the Markdown and
// CSV of a table, the CSV's quoting, the long format of several-number cells,
// the results file's header, and the nearest-rank quantile the benchmarks
// print as p90/p99 (against its definition, counted directly).
#include "experiments/report.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

using namespace ellvor::experiments;

namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

Table example_table() {
    Table t("times", {"set", "n", "time"});
    t.add({"a, b", integer(12), Cell("1.5 ms", "0.0015")});
    t.add({"say \"x\"", integer(-3), cpu_wall(2.0, 0.5)});
    return t;
}

}  // namespace

TEST_CASE("a table's Markdown shows the cells' text, the first column left and the others right", "[report]") {
    const std::vector<std::string> md = lines(example_table().markdown());
    REQUIRE(md.size() == 4);
    CHECK(md[0] == "| set | n | time |");
    CHECK(md[1] == "|---|---:|---:|");
    CHECK(md[2] == "| a, b | 12 | 1.5 ms |");
    CHECK(md[3] == "| say \"x\" | -3 | 2 s (500 ms) |");

    Table aligned("t", {"x", "y", "z"}, "lrl");
    CHECK(lines(aligned.markdown())[1] == "|---|---:|---|");
}

TEST_CASE("a table's CSV keeps the raw values, quoting commas, quotes and line breaks", "[report]") {
    Table t = example_table();
    t.add({"two\nlines", integer(0), Cell("", "")});
    const std::string csv = t.csv();
    CHECK(csv ==
          "set,n,time\n"
          "\"a, b\",12,0.0015\n"
          "\"say \"\"x\"\"\",-3,2 s (500 ms)\n"
          "\"two\nlines\",0,\n");
    CHECK(csv_field("plain") == "plain");
}

TEST_CASE("the long CSV gives one line per value, a several-number cell one line per part", "[report]") {
    const Table t = example_table();
    const std::vector<std::string> csv = lines(long_csv({&t}));
    REQUIRE(csv.size() == 1 + 3 + 4);
    CHECK(csv[0] == "table,row,column,value");
    CHECK(csv[1] == "times,0,set,\"a, b\"");
    CHECK(csv[3] == "times,0,time,0.0015");
    CHECK(csv[6] == "times,1,time [cpu_s],2");
    CHECK(csv[7] == "times,1,time [wall_s],0.5");
}

TEST_CASE("a check's message becomes one line without commas or table bars", "[report]") {
    const std::string m = check_message("edge (1, 2) | missing\nsecond line");
    CHECK(m == "edge (1  2)   missing second line");
    const std::string long_message = check_message(std::string(300, 'x'));
    CHECK(long_message == std::string(120, 'x') + "...");
}

TEST_CASE("the nearest-rank quantile is the smallest value with at least q n values at or below it", "[report]") {
    const std::vector<double> v = {7, 1, 9, 3, 3, 12, 5, 8, 2, 10, 4};
    for (double q : {0.01, 0.1, 0.25, 0.5, 0.9, 0.99, 1.0}) {
        // Counted directly: the least x in v with #{y <= x} >= q n.
        double want = 1e300;
        for (double x : v) {
            std::size_t at_or_below = 0;
            for (double y : v) at_or_below += y <= x;
            if (at_or_below >= q * v.size() && x < want) want = x;
        }
        INFO("q = " << q);
        CHECK(quantile(v, q) == want);
    }
    CHECK(std::isnan(quantile({}, 0.5)));
}

TEST_CASE("a report starts with its title and the run's header, then the measurements", "[report]") {
    Report report("Example", "example_bench", "build/experiments/example_bench --full");
    report.intro("What it measures.");
    report.note("Sets: two.");
    report.heading("Times");
    report.table(example_table(), "Caption.");
    const std::vector<std::string> md = lines(report.markdown());
    REQUIRE(md.size() >= 15);
    CHECK(md[0] == "# Example");
    CHECK(md[2] == "What it measures.");
    CHECK(md[4].rfind("- Machine: ", 0) == 0);
    CHECK(md[5].rfind("- Load average before / after: ", 0) == 0);
    CHECK(md[6].rfind("- Source: ", 0) == 0);
    CHECK(md[7] == "- Command: `make build/experiments/example_bench && build/experiments/example_bench --full`");
    CHECK(md[8] == "- Sets: two.");
    CHECK(md[9] == "");
    CHECK(md[10] == "## Times");
    CHECK(md[12] == "Caption.");
    CHECK(md[14] == "| set | n | time |");
}
