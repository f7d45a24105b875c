#include "ImpactTests.hpp"

#include "ColumnTable.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sdf::fit::breakage
{

const std::vector<std::string>& impactTestColumns()
{
    static const std::vector<std::string> columns =
        {"size", "velocity", "energy", "impacts", "tested", "broken"};
    return columns;
}

std::vector<ImpactTest> readImpactTests(std::istream& stream, const std::string& source)
{
    const ColumnTable table = readColumnTable(stream, source, impactTestColumns());
    for (const char* name : {"size", "impacts", "tested", "broken"})
    {
        if (table.column(name) < 0)
        {
            refuseAt(source, table.headerLine, std::string("no column '") + name
                     + "' (the columns: size, velocity or energy, impacts, tested, broken)");
        }
    }
    const int velocity = table.column("velocity"), energy = table.column("energy");
    if ((velocity >= 0) == (energy >= 0))
    {
        refuseAt(source, table.headerLine, velocity >= 0
            ? "both 'velocity' and 'energy' given: one of them (W = v^2/2)"
            : "neither 'velocity' [m/s] nor 'energy' [J/kg] given");
    }

    if (table.rows.empty()) refuseAt(source, table.headerLine, "no rows after the header");
    std::vector<ImpactTest> tests;
    for (std::size_t r = 0; r < table.rows.size(); ++r)
    {
        const std::vector<double>& row = table.rows[r];
        const int line = table.lines[r];
        auto value = [&](const char* name) { return row[std::size_t(table.column(name))]; };
        ImpactTest t;
        t.line = line;
        t.size = value("size");
        if (!(t.size > 0)) refuseAt(source, line, "column 'size': " + numberText(t.size) + " must be > 0 [m]");
        if (velocity >= 0)
        {
            const double v = row[std::size_t(velocity)];
            if (v < 0) refuseAt(source, line, "column 'velocity': " + numberText(v) + " must be >= 0 [m/s]");
            t.energy = 0.5*v*v;
        }
        else
        {
            t.energy = row[std::size_t(energy)];
            if (t.energy < 0) refuseAt(source, line, "column 'energy': " + numberText(t.energy) + " must be >= 0 [J/kg]");
        }
        // counts beyond any tester, and exact in a double
        t.impacts = int(countAt(value("impacts"), 1, 1e6, source, line, "impacts"));
        t.tested = countAt(value("tested"), 1, 1e15, source, line, "tested");
        t.broken = countAt(value("broken"), 0, 1e15, source, line, "broken");
        if (t.broken > t.tested)
        {
            refuseAt(source, line, "column 'broken': " + std::to_string(t.broken) + " particles broken of "
                     + std::to_string(t.tested) + " tested");
        }
        tests.push_back(t);
    }
    return tests;
}

std::vector<ImpactTest> readImpactTests(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::invalid_argument("cannot open impact tests '" + path + "'");
    return readImpactTests(in, path);
}

} // namespace sdf::fit::breakage
