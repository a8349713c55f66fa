#pragma once
// Mass scaling for cuts at conventional speeds (docs/mass_scaling.md). The explicit step is set by
// the elastic wave speed, so a cut at 1 m/s takes 20x the steps of one at 20 m/s for the same
// travel. Multiplying the workpiece's inertia by f lengthens the step by sqrt(f); what it changes
// is the inertia of the material, measured by the inertia number rho f V^2 / sigma_ref (inertial
// stress of the chip turning at speed V over the flow stress). Quasi-static cutting has
// rho V^2 / sigma_ref << 1; keeping the scaled number small keeps the answer.
#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

// Flow stress that the inertia is compared with, Pa: the Johnson-Cook A (initial yield at the
// reference rate and room temperature); for an elastic material E / 1000.
double reference_flow_stress(const MaterialParameters& m);

// rho f V^2 / sigma_ref, -.
double inertia_number(const MaterialParameters& m, double mass_scaling_factor, double speed);

// The factor the [cutting] preset uses: the given one, or for "auto" (mass_scaling = 0) the one
// that brings the inertia number up to c.mass_scaling_inertia_number, never below 1.
double cutting_mass_scaling_factor(const CuttingParameters& c, const MaterialParameters& m);

// Above this inertia number the scaled inertia starts to change the forces (about 1 %: the
// chip's momentum flux rho f V^2 t0 against the shear force ~ sigma t0); runs warn.
inline constexpr double kInertiaNumberWarning = 1e-2;

}  // namespace mpmcut
