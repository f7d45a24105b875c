#include "fit/OpenFOAMDictionary.hpp"

#include <cctype>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

namespace sdf::fit
{

namespace
{

bool isWord(const std::string& s)
{
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s.front())))
    {
        return false;
    }
    for (const char c : s)
    {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.')
        {
            return false;
        }
    }
    return true;
}

//- Keyword padded to a column, as OpenFOAM's own dictionaries are laid out.
std::string key(const std::string& k, std::size_t width = 16)
{
    return k.size() < width ? k + std::string(width - k.size(), ' ') : k + ' ';
}

std::string range(const Range& r)
{
    std::ostringstream s;
    s << std::setprecision(10) << '(' << r.min << ' ' << r.max << ')';
    return s.str();
}

void writeCoefficient(std::ostream& os, const CalibratedCoefficient& entry)
{
    const FitResult& fit = entry.fit;
    const std::string in1 = "    ", in2 = "        ";
    os << entry.coefficient << "\n{\n";
    os << in1 << key("law") << fit.law.name() << ";\n";
    os << in1 << key("formula") << '"' << fit.law.formula() << "\";\n";
    for (const auto& [name, value] : fit.law.fixedEntries())
    {
        os << in1 << key(name) << value << ";\n";
    }
    for (const FittedParameter& p : fit.parameters)
    {
        os << in1 << key(p.name) << p.value << ";\n";
    }
    os << in1 << "errors\n" << in1 << "{\n";
    for (const FittedParameter& p : fit.parameters)
    {
        os << in2 << key(p.name, 12) << p.standardError << ";\n";
    }
    os << in1 << "}\n";
    // Covariance in parameter order, for propagating the calibration's
    // uncertainty (e.g. solver runs at correlated +-1 sigma parameters).
    os << in1 << key("covariance") << '(';
    for (Eigen::Index i = 0; i < fit.covariance.rows(); ++i)
    {
        os << (i ? " (" : "(");
        for (Eigen::Index j = 0; j < fit.covariance.cols(); ++j)
        {
            os << (j ? " " : "") << fit.covariance(i, j);
        }
        os << ')';
    }
    os << ");\n";
    os << in1 << key("R2") << fit.rSquared << ";\n";
    os << in1 << key("chi2") << fit.chiSquare << ";\n";
    os << in1 << key("reducedChi2") << fit.reducedChiSquare << ";\n";
    os << in1 << key("AIC") << fit.aic << ";\n";
    os << in1 << key("BIC") << fit.bic << ";\n";
    os << in1 << key("points") << fit.points << ";\n";
    os << in1 << key("fitSpace") << (fit.space == FitSpace::logarithmic ? "log" : "linear")
       << ";\n";
    os << in1 << key("sigma")
       << (fit.sigmaMeaning == SigmaMeaning::relative ? "relative" : "absolute") << ";\n";
    os << in1 << key("phiRange") << range(fit.envelope.phi) << ";\n";
    os << in1 << key("xRange") << range(fit.envelope.x) << ";\n";
    os << in1 << key("TRange") << range(fit.envelope.T) << ";\n";
    os << in1 << key("dRange") << range(fit.envelope.d) << ";\n";
    if (fit.envelope.gammaDot)
    {
        os << in1 << key("gammaDotRange") << range(*fit.envelope.gammaDot) << ";\n";
    }
    for (const auto& [name, value] : entry.provenance)
    {
        os << in1 << key(name) << value << ";\n";
    }
    if (entry.selection)
    {
        const ModelSelection& s = *entry.selection;
        os << in1 << "selection\n" << in1 << "{\n";
        os << in2 << key("criterion", 24) << toString(s.criterion) << ";\n";
        os << in2 << "// delta" << toString(s.criterion) << " of each candidate (0: best)\n";
        for (const RankedLaw& r : s.ranking)
        {
            os << in2 << key(r.law, 24) << r.delta << ";\n";
        }
        if (!s.failed.empty())
        {
            os << in2 << key("failed", 24) << '(';
            for (std::size_t i = 0; i < s.failed.size(); ++i)
            {
                os << (i ? " " : "") << s.failed[i].first;
            }
            os << ");\n";
        }
        os << in1 << "}\n";
    }
    os << "}\n\n";
}

const std::string in1 = "    ";

//- y = A phi^b with its errors; weighted fits give their reduced chi2, a
//  unit-weight fit (R) the rms scatter of ln y about the law instead
void writePhiLaw
(
    std::ostream& os,
    const std::string& name,
    const PhiPowerLaw& law,
    bool unitWeights
)
{
    if (!law.fitted)
    {
        return;
    }
    os << in1 << key(name) << "{ A " << law.A << "; AError " << law.AError
       << "; b " << law.b << "; bError " << law.bError << "; "
       << (unitWeights ? "lnScatter " : "reducedChi2 ")
       << (unitWeights ? std::sqrt(law.reducedChiSquare) : law.reducedChiSquare)
       << "; }\n";
}

void writeShearScaling(std::ostream& os, const ShearScaling& s)
{
    os << "// Sheared calibration (Lees-Edwards cells, T measured): the fines' D across\n"
          "// the shear in units of gammaDot dMean^2, and R = dMean gammaDot sqrt(3/T).\n"
          "// C: diffusivity { model shearRate; shearRateCoeffs { C ..; } } (Fan et al.\n"
          "// 2014 found 0.042); R: granularTemperature { model savageJeffrey;\n"
          "// savageJeffreyCoeffs { R ..; } }. *PhiLaw: y = A phi^b.\n";
    os << "shearScaling\n{\n";
    os << in1 << key("C") << s.meanC.value << ";\n";
    os << in1 << key("CError") << s.meanC.error << ";\n";
    os << in1 << key("CReducedChi2") << s.meanC.reducedChiSquare << ";\n";
    writePhiLaw(os, "CPhiLaw", s.CLaw, false);
    os << in1 << key("R") << s.meanR << ";\n";
    os << in1 << key("RSpread") << s.spreadR << ";\n";
    writePhiLaw(os, "RPhiLaw", s.RLaw, true);
    os << in1 << key("points") << s.C.size() << ";\n";
    os << in1 << key("phiRange") << range(s.phi) << ";\n";
    os << in1 << key("xRange") << range(s.x) << ";\n";
    os << in1 << key("gammaDotRange") << range(s.gammaDot) << ";\n";
    os << "}\n\n";
}

} // namespace

std::string coefficientsFileHeader()
{
    return
        "/*--------------------------------*- C++ -*----------------------------------*\\\n"
        "  granularCoefficients: constitutive laws fitted to DEM results (sdf::fit)\n"
        "\\*---------------------------------------------------------------------------*/\n"
        "FoamFile\n"
        "{\n"
        "    version     2.0;\n"
        "    format      ascii;\n"
        "    class       dictionary;\n"
        "    location    \"constant\";\n"
        "    object      granularCoefficients;\n"
        "}\n";
}


void writeOpenFOAMDictionary
(
    std::ostream& os,
    const std::vector<CalibratedCoefficient>& coefficients,
    const ShearScaling* shear
)
{
    if (coefficients.empty())
    {
        throw std::invalid_argument("writeOpenFOAMDictionary: no coefficients to write");
    }
    std::set<std::string> seen;
    for (std::size_t i = 0; i < coefficients.size(); ++i)
    {
        const CalibratedCoefficient& c = coefficients[i];
        std::ostringstream where;
        where << "writeOpenFOAMDictionary: coefficient " << i << " ('" << c.coefficient << "')";
        if (!isWord(c.coefficient))
        {
            throw std::invalid_argument(where.str() + ": name is not an OpenFOAM word");
        }
        if (!seen.insert(c.coefficient).second)
        {
            throw std::invalid_argument(where.str() + ": name given twice");
        }
        if (!c.fit.converged())
        {
            throw FitFailure(where.str() + ": refusing to write a failed fit: " + c.fit.message);
        }
    }

    // Format everything in a local stream: the caller's stream flags stay as they were.
    std::ostringstream text;
    text << std::setprecision(10);
    text << coefficientsFileHeader() <<
        "// phi: total solids fraction; x: coarse fraction of the solids;\n"
        "// T: granular temperature, SUM of the three components [m2/s2] (T1 = T/3);\n"
        "// d: diameter of the species the coefficient belongs to [m].\n"
        "// errors: standard errors; *Range: the envelope the law was fitted on.\n\n";
    for (const CalibratedCoefficient& c : coefficients)
    {
        writeCoefficient(text, c);
    }
    if (shear)
    {
        writeShearScaling(text, *shear);
    }
    text << "// ************************************************************************* //\n";
    os << text.str();
}

} // namespace sdf::fit
