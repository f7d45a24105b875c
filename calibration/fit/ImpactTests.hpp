// Single-particle impact tests (an Aston-type or Vogel & Peukert's impact tester): per
// row, the particles' size, their impact speed or mass-specific energy, the number of
// impacts each suffered, how many particles were tested and how many broke. The table
// fitBreakageParameters fits the Vogel-Peukert constants to (BreakageFit.hpp).
//
// The file (ColumnTable.hpp's form): '#' starts a comment; the first other line names the
// columns, whitespace-separated, in any order: size [m], velocity [m/s] or energy [J/kg] (W = v^2/2; one of
// the two), impacts, tested, broken; every following line gives one test, numbers only.
#ifndef sdf_fit_ImpactTests_hpp
#define sdf_fit_ImpactTests_hpp

#include <iosfwd>
#include <string>
#include <vector>

namespace sdf::fit::breakage
{

//- One row of impact tests.
struct ImpactTest
{
    double size = 0;       // particle size x [m]
    double energy = 0;     // mass-specific impact energy W [J/kg] (v^2/2 from a velocity)
    int impacts = 1;       // impacts each particle suffered, k
    long tested = 0;       // particles tested, n
    long broken = 0;       // particles broken, b
    int line = 0;          // line in the file (messages)
};

//- The column names a table may use.
const std::vector<std::string>& impactTestColumns();

//- Reads a table of impact tests from stream, source naming it in messages. Throws
//  std::invalid_argument naming source, line and column for: no header (or numbers
//  before it), an unknown or repeated column, a missing column, velocity and energy both
//  or neither, a value that is not a finite number, a size <= 0, tested < 1, a negative
//  velocity or energy, impacts < 1 (or above 1e6), broken < 0 or broken > tested, a count
//  above 1e15, a row of the wrong length, no rows.
std::vector<ImpactTest> readImpactTests(std::istream& stream, const std::string& source);

//- The same from a file (std::invalid_argument when it cannot be opened).
std::vector<ImpactTest> readImpactTests(const std::string& path);

} // namespace sdf::fit::breakage

#endif
