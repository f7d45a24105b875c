// A whitespace-separated table of numbers under a header line naming its columns, as
// measurement tables come (impact tests, sieve analyses): '#' starts a comment, blank
// lines are skipped, every value must be a finite number. The readers of such tables
// (ImpactTests, FragmentSieving) check the values' meaning; this checks the form.
#ifndef sdf_fit_ColumnTable_hpp
#define sdf_fit_ColumnTable_hpp

#include <iosfwd>
#include <string>
#include <vector>

namespace sdf::fit
{

struct ColumnTable
{
    std::string source;                    // the file's name, for messages
    std::vector<std::string> columns;      // as the header names them
    std::vector<std::vector<double>> rows; // one value per column
    std::vector<std::string> text;         // the values as written, per row, joined by ' '
    std::vector<int> lines;                // each row's line in the file
    int headerLine = 0;

    //- The index of column name, or -1
    int column(const std::string& name) const;
};

//- value as messages and dictionaries print it (6 significant digits)
std::string numberText(double value);

//- Throws std::invalid_argument "source:line: what".
[[noreturn]] void refuseAt(const std::string& source, int line, const std::string& what);

//- Reads the table. Throws std::invalid_argument naming source and line for: numbers
//  before a header, a column not among valid (with the valid ones) or given twice, a row
//  of the wrong length, a value that is not a finite number (naming its column). No rows
//  is the caller's to refuse (after it has checked the columns).
ColumnTable readColumnTable
(
    std::istream& stream,
    const std::string& source,
    const std::vector<std::string>& valid
);

//- value as a count: a whole number in [minimum, maximum], else refuseAt naming column.
long countAt(double value, long minimum, double maximum, const std::string& source, int line,
             const std::string& column);

} // namespace sdf::fit

#endif
