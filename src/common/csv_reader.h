// Reading CSV files row by row, with the line of each row for error messages.
//
// The one way echoplan reads the CSV it is given (recording manifests, feature sets, groups):
// comma-separated fields, optionally quoted ("a,b" is one field, "" inside quotes is one quote),
// one row per line (a quoted field cannot span lines), blank lines skipped, a trailing '\r' (CRLF
// files) ignored. Values are not trimmed: " 1" is the text " 1".
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace echoplan {

// Splits one CSV line into `fields` (cleared first), undoing the quoting above; '\r' outside quotes
// is dropped. "a,b," gives three fields, the last empty. Returns false on an unterminated quote.
bool split_csv_line(std::string_view line, std::vector<std::string>& fields);

// The rows of one CSV text. Rows come in file order; line() names the row last read.
class CsvReader {
 public:
  // `text` is the whole file (common/file_io.h read_text_file); `file` names it in messages. The
  // reader keeps a copy of the text.
  CsvReader(std::string text, std::string file);

  // The next row that is not blank into `fields`; false at the end of the text. Throws
  // InputError(file, line, "unterminated quote ...") for a broken row.
  bool next(std::vector<std::string>& fields);

  // 1-based line of the row last returned by next() (0 before the first).
  int line() const { return line_; }
  const std::string& file() const { return file_; }

 private:
  std::string text_;
  std::string file_;
  std::size_t position_ = 0;  // start of the next line in text_
  int line_ = 0;              // lines consumed so far
};

}  // namespace echoplan
