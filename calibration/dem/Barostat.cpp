#include "Barostat.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::dem
{

Barostat::Barostat(double targetPressure, double relaxationTime, double timeStep)
:
    targetPressure_(targetPressure),
    relaxationTime_(relaxationTime),
    timeStep_(timeStep)
{
    if (!(targetPressure > 0) || !std::isfinite(targetPressure))
    {
        throw std::invalid_argument
        (
            "targetPressure must be a finite pressure > 0 Pa for a pressure-controlled cell"
            " (0: volume-controlled), not " + std::to_string(targetPressure)
        );
    }
    if (!(relaxationTime > 0) || !std::isfinite(relaxationTime))
    {
        throw std::invalid_argument
        (
            "barostatTime must be > 0 s (0 in the settings: automatic), not "
          + std::to_string(relaxationTime)
        );
    }
}

double Barostat::automaticRelaxationTime
(
    double contactStiffness, double dMin, double targetPressure, double timeStep
)
{
    return 5.0*every*timeStep*contactStiffness/(targetPressure*dMin);
}

double Barostat::dilation(double sigmaYY) const
{
    double strain = every*timeStep_/relaxationTime_*(sigmaYY/targetPressure_ - 1);
    strain = std::clamp(strain, -maxStrainPerUpdate, maxStrainPerUpdate);
    return std::exp(strain);
}

} // namespace sdf::dem
