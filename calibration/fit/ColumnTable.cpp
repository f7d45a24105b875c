#include "ColumnTable.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sdf::fit
{

namespace
{

std::string joined(const std::vector<std::string>& words)
{
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
    return out;
}

// The line without its comment, split into words
std::vector<std::string> words(const std::string& text)
{
    std::istringstream in(text.substr(0, text.find('#')));
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

bool parse(const std::string& word, double& value)
{
    std::size_t used = 0;
    try { value = std::stod(word, &used); } catch (const std::exception&) { return false; }
    return used == word.size() && std::isfinite(value);
}

} // namespace

std::string numberText(double value)
{
    std::ostringstream s;
    s << value;
    return s.str();
}

int ColumnTable::column(const std::string& name) const
{
    const auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? -1 : int(it - columns.begin());
}

void refuseAt(const std::string& source, int line, const std::string& what)
{
    throw std::invalid_argument(source + ":" + std::to_string(line) + ": " + what);
}

ColumnTable readColumnTable
(
    std::istream& stream,
    const std::string& source,
    const std::vector<std::string>& valid
)
{
    ColumnTable table;
    table.source = source;
    std::string text;
    int line = 0;
    while (std::getline(stream, text))
    {
        ++line;
        const std::vector<std::string> row = words(text);
        if (row.empty()) continue;
        if (table.columns.empty())
        {
            double x = 0;
            if (std::all_of(row.begin(), row.end(), [&](const std::string& w) { return parse(w, x); }))
            {
                refuseAt(source, line, "numbers before a header line naming the columns (" + joined(valid) + ")");
            }
            for (const std::string& name : row)
            {
                if (std::find(valid.begin(), valid.end(), name) == valid.end())
                {
                    refuseAt(source, line, "unknown column '" + name + "'; valid columns: " + joined(valid));
                }
                if (table.column(name) >= 0) refuseAt(source, line, "column '" + name + "' given twice");
                table.columns.push_back(name);
            }
            table.headerLine = line;
            continue;
        }
        if (row.size() != table.columns.size())
        {
            refuseAt(source, line, std::to_string(row.size()) + " values for "
                     + std::to_string(table.columns.size()) + " columns (" + joined(table.columns) + ")");
        }
        std::vector<double> values(row.size());
        for (std::size_t c = 0; c < row.size(); ++c)
        {
            if (!parse(row[c], values[c]))
            {
                refuseAt(source, line, "column '" + table.columns[c] + "': '" + row[c] + "' is not a finite number");
            }
        }
        table.rows.push_back(values);
        table.text.push_back(joined(row));
        table.lines.push_back(line);
    }
    if (table.columns.empty()) refuseAt(source, std::max(line, 1), "no header line naming the columns (" + joined(valid) + ")");
    return table;
}

long countAt(double value, long minimum, double maximum, const std::string& source, int line,
             const std::string& column)
{
    if (value != std::floor(value) || value < double(minimum) || value > maximum)
    {
        std::ostringstream msg;
        msg << "column '" << column << "': " << value << " must be a whole number >= " << minimum
            << " (and at most " << maximum << ")";
        refuseAt(source, line, msg.str());
    }
    return long(value);
}

} // namespace sdf::fit
