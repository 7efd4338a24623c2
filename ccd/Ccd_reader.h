// Reading CCD queries (docs/ccd-queries.md, Input): the benchmark's CSV (8
// rows of 7 integers per query) or JSON lines (a query per line), read
// exactly, a batch at a time, so that files of millions of queries stream.
// Bad input is an Input_error naming the line and column ("line 17, column
// 9"): exit 2, or 3 for a limit.
#ifndef CLASH4D_CCD_CCD_READER_H
#define CLASH4D_CCD_CCD_READER_H

#include "ccd/Ccd_query.h"
#include "scene/Json_value.h"
#include <fstream>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace clash4d {

// A line longer than this is refused (exit 3): no query needs it (seven
// numbers of at most 1,000 digits each, or a JSON line of eight points).
constexpr std::size_t CLASH4D_MAX_CCD_LINE = 1u << 20;

// The type a file's path names: its name's beginning, or else the nearest
// folder's, "vertex-face" or "edge-edge".
std::optional<Ccd_type> ccd_type_from_path(const std::string& path);

class Ccd_reader {
public:
  enum class Format { csv, json_lines };

  // Opens a file; its format is its extension's (.csv; .json, .jsonl,
  // .ndjson) or else its first character's ('{': JSON lines). The type is
  // `type` (--type), or else the path's; a CSV file needs one of them.
  // Throws Input_error (no place) when the file cannot be read or typed.
  Ccd_reader(const std::string& path, std::optional<Ccd_type> type);
  // Reads text from a stream (tests, the fuzz target).
  Ccd_reader(std::istream& in, Format format, std::optional<Ccd_type> type);

  // Appends up to `count` queries to `out`; returns how many (0 at the end).
  // The queries are parsed on all cores; the error is the first bad one's.
  std::size_t read(std::size_t count, std::vector<Ccd_query>& out);
  Format format() const { return format_; }

private:
  struct Text;
  bool next_line(std::string& line);
  bool take_csv(Text& t);
  bool take_json_line(Text& t);
  Ccd_query parse_csv(const Text& t) const;
  Ccd_query parse_json_line(const Text& t) const;
  Ccd_query json_query(const Json_value& v, std::size_t line) const;

  std::unique_ptr<std::ifstream> file_;
  std::istream* in_;
  Format format_;
  std::optional<Ccd_type> type_;   // --type's, or else the path's
  bool type_given_;                 // --type's: a line's own type must agree
  std::size_t line_ = 0;   // the last line read, from 1
};

} // namespace clash4d

#endif
