// The report writer of the benchmark programs: tables of measurements written
// as Markdown (for reading) and CSV (for plots and later comparison), and the
// results file's header (machine, load, source, command).
#pragma once

#include "experiments/run_environment.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ellvor::experiments {

// ------------------------------------------------------------- formatting --

// printf-style formatting of one number.
inline std::string fmt(const char* format, double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, x);
    return buf;
}

// A duration with a unit chosen for it.
inline std::string duration(double s) {
    if (s >= 1) return fmt("%.3g s", s);
    if (s >= 1e-3) return fmt("%.3g ms", 1e3 * s);
    return fmt("%.3g µs", 1e6 * s);
}

// A message on one table line: no newline or '|', at most `limit` characters.
inline std::string one_line(std::string s, std::size_t limit = 160) {
    for (char& c : s)
        if (c == '\n' || c == '|') c = ' ';
    if (s.size() > limit) s = s.substr(0, limit) + "...";
    return s;
}

// A check's message as a table cell and a plain CSV field: one line of at
// most 120 characters, without commas.
inline std::string check_message(const std::string& s) {
    std::string t = one_line(s, 120);
    for (char& c : t)
        if (c == ',') c = ' ';
    return t;
}

// A CSV field, quoted when it holds a comma, a quote or a line break.
inline std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string o = "\"";
    for (char ch : s) o += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return o + "\"";
}

// ------------------------------------------------------------------ tables --

// A table cell: what the Markdown shows and what the CSV keeps (raw numbers in
// SI units, or the same text). A cell of several numbers keeps each under the
// column's name with a suffix ("... [cpu_s]") in the long CSV format.
struct Cell {
    std::string text, raw;
    std::vector<std::pair<std::string, std::string>> parts;  // (suffix, raw value)
    Cell(std::string t) : text(t), raw(std::move(t)) {}  // NOLINT: text cells are the common case
    Cell(const char* t) : Cell(std::string(t)) {}        // NOLINT
    Cell(std::string t, std::string r) : text(std::move(t)), raw(std::move(r)) {}
};

inline Cell integer(long long v) { return Cell(std::to_string(v)); }
inline Cell seconds_cell(double s) { return Cell(duration(s), fmt("%.6g", s)); }
// "CPU (wall)".
inline Cell cpu_wall(double cpu, double wall) {
    Cell c(duration(cpu) + " (" + duration(wall) + ")");
    c.parts = {{"cpu_s", fmt("%.6g", cpu)}, {"wall_s", fmt("%.6g", wall)}};
    return c;
}

using TableRow = std::vector<Cell>;

// A table of measurements. Markdown alignment: one character per column, 'l'
// or 'r' (by default the first column left, the others right).
struct Table {
    Table(std::string id_, std::vector<std::string> columns_, std::string align_ = "")
        : id(std::move(id_)), columns(std::move(columns_)), align(std::move(align_)) {}

    std::string id;  // its name in a long-format CSV
    std::vector<std::string> columns;
    std::string align;
    std::vector<TableRow> rows;

    void add(TableRow row) { rows.push_back(std::move(row)); }

    std::string markdown() const {
        std::ostringstream md;
        md << "|";
        for (const std::string& c : columns) md << " " << c << " |";
        md << "\n|";
        for (std::size_t i = 0; i < columns.size(); ++i) {
            const char a = i < align.size() ? align[i] : (i == 0 ? 'l' : 'r');
            md << (a == 'r' ? "---:|" : "---|");
        }
        md << "\n";
        for (const TableRow& row : rows) {
            md << "|";
            for (const Cell& c : row) md << " " << c.text << " |";
            md << "\n";
        }
        return md.str();
    }

    // Wide format: a header line of the columns, then one line per row of the raw values.
    std::string csv() const {
        std::ostringstream out;
        for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << csv_field(columns[c]);
        out << "\n";
        for (const TableRow& row : rows) {
            for (std::size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << csv_field(row[c].raw);
            out << "\n";
        }
        return out.str();
    }

    // Long format, one line per value: table,row,column,value (a cell of
    // several numbers gives one line each, the column suffixed).
    void csv_long(std::ostream& out) const {
        for (std::size_t r = 0; r < rows.size(); ++r)
            for (std::size_t c = 0; c < rows[r].size() && c < columns.size(); ++c) {
                const Cell& cell = rows[r][c];
                if (cell.parts.empty())
                    out << id << "," << r << "," << csv_field(columns[c]) << "," << csv_field(cell.raw) << "\n";
                for (const auto& [suffix, value] : cell.parts)
                    out << id << "," << r << "," << csv_field(columns[c] + " [" + suffix + "]") << ","
                        << csv_field(value) << "\n";
            }
    }
};

// Tables in the long CSV format, after one header line.
inline std::string long_csv(const std::vector<const Table*>& tables) {
    std::ostringstream csv;
    csv << "table,row,column,value\n";
    for (const Table* t : tables) t->csv_long(csv);
    return csv.str();
}

// A target a benchmark checks: what, the measured value, met or not.
struct Target {
    std::string what, measured;
    bool met;
};

// "- WHAT: MEASURED — met" lines.
inline std::string target_lines(const std::vector<Target>& targets) {
    std::string s;
    for (const Target& t : targets) s += "- " + t.what + ": " + t.measured + " — " + (t.met ? "met" : "MISSED") + "\n";
    return s;
}

// ------------------------------------------------------------------ report --

// A results file: a title, what the program measures, the run's header, then
// the measurements in order (tables with short captions). The load average is
// read when the report is made and again when the header is written.
class Report {
public:
    // `program`: the benchmark's name under build/experiments/.
    Report(std::string title, std::string program, std::string command)
        : title_(std::move(title)), program_(std::move(program)), command_(std::move(command)),
          load_before_(loadavg()), source_(source_state()) {}  // the source as it is at the start

    // A paragraph between the title and the header.
    void intro(const std::string& text) { intro_ += text + "\n\n"; }
    // A line of the header list ("- ...").
    void note(const std::string& line) { notes_ += "- " + line + "\n"; }
    // Said after the machine's name (e.g. that it is shared).
    void machine_note(const std::string& text) { machine_note_ = text; }

    // A section heading.
    void heading(const std::string& title, int level = 2) {
        body_ << "\n" << std::string(static_cast<std::size_t>(level), '#') << " " << title << "\n\n";
    }
    // Free Markdown (a caption, a list).
    void text(const std::string& markdown) { body_ << markdown; }
    void paragraph(const std::string& text) { body_ << text << "\n\n"; }
    // A table with its caption (empty: none).
    void table(const Table& t, const std::string& caption = "") {
        if (!caption.empty()) body_ << caption << "\n\n";
        body_ << t.markdown();
    }

    // The whole document; reads the load average after the run (once).
    std::string markdown() {
        if (load_after_.empty()) load_after_ = loadavg();
        std::ostringstream md;
        md << "# " << title_ << "\n\n" << intro_;
        md << "- Machine: " << cpu_model() << (machine_note_.empty() ? "" : " (" + machine_note_ + ")") << "\n"
           << "- Load average before / after: " << load_before_ << " / " << load_after_ << "\n"
           << "- Source: " << source_ << "\n"
           << "- Command: `make build/experiments/" << program_ << " && " << command_ << "`\n"
           << notes_;
        std::string body = body_.str();
        if (body.rfind("\n", 0) != 0) md << "\n";
        md << body;
        return md.str();
    }

    // Prints the report and, when out_dir is not empty, writes it to
    // out_dir/md_name and each further file (name, text) beside it.
    void publish(const std::string& out_dir, const std::string& md_name,
                 const std::vector<std::pair<std::string, std::string>>& files = {});

private:
    std::string title_, program_, command_, load_before_, source_, load_after_, intro_, notes_, machine_note_;
    std::ostringstream body_;
};

// Writes DIR/NAME with `text` (making DIR if needed), and says so on stderr;
// throws std::runtime_error when it cannot (a missing directory used to pass
// silently, the results lost).
inline void write_result(const std::string& dir, const std::string& name, const std::string& text) {
    std::filesystem::create_directories(dir);
    std::ofstream out(dir + "/" + name);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + dir + "/" + name);
    std::cerr << "[" << name << "] written to " << dir << "/" << name << "\n";
}

inline void Report::publish(const std::string& out_dir, const std::string& md_name,
                            const std::vector<std::pair<std::string, std::string>>& files) {
    const std::string md = markdown();
    std::cout << md;
    if (out_dir.empty()) return;
    for (const auto& [name, text] : files) write_result(out_dir, name, text);
    write_result(out_dir, md_name, md);
}

}  // namespace ellvor::experiments
