#ifndef sdf_dem_Barostat_hpp
#define sdf_dem_Barostat_hpp

// Pressure control of a Lees-Edwards sheared cell: the normal stress across the shear,
// sigma_yy, is held at a target pressure p by dilating the cell's gradient (y) extent
// affinely (positions y and the box length ly scaled by one factor; velocities kept, as
// LAMMPS' fix press/berendsen remaps them). Plane shear at controlled normal stress is
// how the granular-rheology literature measures mu(I) and phi(I) (GDR MiDi 2004; da Cruz
// et al. 2005): the solids fraction is then an output, as in a silo, not an input.
//
// The law (weak coupling, applied every `every` steps from sigma_yy measured then):
//     ln(ly_new/ly) = (every dt / tau_p) (sigma_yy/p - 1),  clamped to +-maxStrainPerUpdate.
// The relative pressure error drives the strain rate, so a loose start (sigma_yy ~ 0)
// compresses at 1/tau_p whatever the stiffness. In a dense packing sigma_yy responds to
// strain with a modulus of at most about k/d (k the contact stiffness): the loop gain per
// update is then every dt k/(p d tau_p), and the automatic tau_p makes it 1/5. sigma_yy
// answers a dilation over a sound-crossing time (hundreds of steps), not within an update:
// the loop is an integrator with a delay, stable while its gain over that delay stays
// below 1 (the steady checks of the tests and benchmarks hold it). In inertial flow the modulus is far below k/d (sigma_yy ~ (phi_c - phi)^-2,
// d ln sigma/d ln phi ~ 40 at I 0.3 against k/(p d) ~ 1000), so the density relaxes over
// a fraction of a strain there; 1/20 made that several strains, longer than the blocks.

namespace sdf::dem
{

class Barostat
{
public:
    //- Steps between updates (sigma_yy is a pass over the contacts: every 10 steps it costs
    //  a few per cent of a step's time)
    static constexpr int every = 10;
    //- Largest |ln s| per update (a start far from the target, e.g. an overlapping
    //  packing, cannot crush or explode the cell in one update)
    static constexpr double maxStrainPerUpdate = 1e-3;

    //- targetPressure > 0 [Pa]; relaxationTime tau_p > 0 [s]; timeStep dt [s]
    Barostat(double targetPressure, double relaxationTime, double timeStep);

    //- tau_p giving a loop gain of 1/5 in a dense packing: 5 every dt k/(p dMin), with k
    //  the stiffest pair's normal contact stiffness at the contact force p d^2
    static double automaticRelaxationTime
    (
        double contactStiffness, double dMin, double targetPressure, double timeStep
    );

    double targetPressure() const { return targetPressure_; }
    double relaxationTime() const { return relaxationTime_; }

    //- The factor s the gradient extent is multiplied by, given sigma_yy now [Pa]
    double dilation(double sigmaYY) const;

private:
    double targetPressure_;
    double relaxationTime_;
    double timeStep_;
};

} // namespace sdf::dem

#endif
