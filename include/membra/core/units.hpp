#pragma once
// Unit conversions. Scenes and outputs use mm, MPa, g/cm^3, s (force in N); the model state is
// SI (m, Pa, kg, s). Multiply an input value by the constant to get SI.
namespace membra::units {

inline constexpr double mm = 1e-3;                   // m per mm
inline constexpr double MPa = 1e6;                   // Pa per MPa
inline constexpr double g_per_cm3 = 1e3;             // kg/m^3 per g/cm^3
inline constexpr double N_per_mm = 1e3;              // N/m per N/mm
inline constexpr double standard_gravity = 9.80665;  // m/s^2

}  // namespace membra::units
