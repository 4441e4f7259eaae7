// Physical units accepted in case files: a small table of unit symbols, each with its SI
// factor and dimension, and the parser of quantity strings such as "210 GPa" or "4 µm".
//
// Case files speak the units of MEMS papers (µm, GPa, kg/m^3); everything inside the code is
// SI. A bare number is taken as SI. Only multiplicative units exist (K, no °C).
#pragma once
#include <string>
#include <string_view>

namespace rfmems {

enum class Dimension {
  Dimensionless,
  Length,
  Pressure,  // also stress and elastic moduli
  Time,
  Density,
  Force,
  ForcePerLength,  // spring constants, line loads
  Moment,          // torque, point moments (N*m); a moment per unit length is a Force
  Voltage,
  Frequency,
  Mass,
  Temperature,
  Velocity,
  Viscosity,  // dynamic viscosity (gas damping)
};

// "length", "pressure", ... for error messages.
std::string dimension_name(Dimension d);

// The SI unit's symbol ("m", "Pa", "Pa s"); "" for a dimensionless number.
std::string si_unit(Dimension d);

// A few accepted symbols of a dimension, e.g. "Pa, kPa, MPa, GPa, atm, bar, torr".
std::string example_units(Dimension d);

struct Unit {
  double factor;  // SI value of one unit
  Dimension dimension;
};

// The unit with this symbol, or nullptr. Both the micro sign (U+00B5) and the Greek mu
// (U+03BC) are read as 'u'; "m3" is read as "m^3".
const Unit* find_unit(std::string_view symbol);

// Parses "<number>" (SI) or "<number> <unit>" (the space is optional) and returns the SI
// value. Throws std::invalid_argument with a short reason (no file or key: the caller adds
// them) when the number is malformed, the unit unknown, or of another dimension.
double parse_quantity(std::string_view text, Dimension expected);

// Parses a whole string as a finite real number (no unit); false if it is not one.
// Locale-independent; accepts a leading '+'.
bool parse_real(std::string_view text, double& value);

}  // namespace rfmems
