// The unit table and the quantity parser declared in units.hpp.
#include "io/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace rfmems {

namespace {

struct UnitEntry {
  std::string_view symbol;  // as shown in messages; compared after normalise_symbol
  Unit unit;
};

using D = Dimension;

// Symbols are case-sensitive (MPa is not mPa). Keep the entries of a dimension together: the
// examples in error messages are taken from here.
constexpr std::array kUnits = {
    UnitEntry{"m", {1.0, D::Length}},
    UnitEntry{"cm", {1e-2, D::Length}},
    UnitEntry{"mm", {1e-3, D::Length}},
    UnitEntry{"um", {1e-6, D::Length}},
    UnitEntry{"nm", {1e-9, D::Length}},

    UnitEntry{"Pa", {1.0, D::Pressure}},
    UnitEntry{"kPa", {1e3, D::Pressure}},
    UnitEntry{"MPa", {1e6, D::Pressure}},
    UnitEntry{"GPa", {1e9, D::Pressure}},
    UnitEntry{"atm", {101325.0, D::Pressure}},
    UnitEntry{"bar", {1e5, D::Pressure}},
    UnitEntry{"mbar", {1e2, D::Pressure}},
    UnitEntry{"torr", {101325.0 / 760.0, D::Pressure}},
    UnitEntry{"Torr", {101325.0 / 760.0, D::Pressure}},

    UnitEntry{"s", {1.0, D::Time}},
    UnitEntry{"ms", {1e-3, D::Time}},
    UnitEntry{"us", {1e-6, D::Time}},
    UnitEntry{"ns", {1e-9, D::Time}},
    UnitEntry{"min", {60.0, D::Time}},
    UnitEntry{"h", {3600.0, D::Time}},
    UnitEntry{"d", {86400.0, D::Time}},

    UnitEntry{"kg/m^3", {1.0, D::Density}},
    UnitEntry{"g/cm^3", {1e3, D::Density}},

    UnitEntry{"N", {1.0, D::Force}},
    UnitEntry{"mN", {1e-3, D::Force}},
    UnitEntry{"uN", {1e-6, D::Force}},
    UnitEntry{"nN", {1e-9, D::Force}},

    UnitEntry{"N*m", {1.0, D::Moment}},
    UnitEntry{"uN*m", {1e-6, D::Moment}},
    UnitEntry{"nN*m", {1e-9, D::Moment}},

    UnitEntry{"N/m", {1.0, D::ForcePerLength}},
    UnitEntry{"mN/m", {1e-3, D::ForcePerLength}},

    UnitEntry{"V", {1.0, D::Voltage}},
    UnitEntry{"mV", {1e-3, D::Voltage}},
    UnitEntry{"kV", {1e3, D::Voltage}},

    UnitEntry{"Hz", {1.0, D::Frequency}},
    UnitEntry{"kHz", {1e3, D::Frequency}},
    UnitEntry{"MHz", {1e6, D::Frequency}},
    UnitEntry{"GHz", {1e9, D::Frequency}},

    UnitEntry{"kg", {1.0, D::Mass}},
    UnitEntry{"g", {1e-3, D::Mass}},
    UnitEntry{"mg", {1e-6, D::Mass}},
    UnitEntry{"ug", {1e-9, D::Mass}},
    UnitEntry{"ng", {1e-12, D::Mass}},

    UnitEntry{"K", {1.0, D::Temperature}},

    UnitEntry{"m/s", {1.0, D::Velocity}},
    UnitEntry{"mm/s", {1e-3, D::Velocity}},
    UnitEntry{"um/s", {1e-6, D::Velocity}},

    UnitEntry{"Pa s", {1.0, D::Viscosity}},  // also "Pa*s", "Pa.s", "Pa·s"
    UnitEntry{"mPa s", {1e-3, D::Viscosity}},
    UnitEntry{"uPa s", {1e-6, D::Viscosity}},
};

// Spellings that mean the same unit are brought to the table's form: micro signs become 'u',
// products lose their separator, and a trailing "m3" becomes "m^3".
std::string normalise_symbol(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const auto next = i + 1 < s.size() ? static_cast<unsigned char>(s[i + 1]) : 0u;
    if ((c == 0xC2 && next == 0xB5) || (c == 0xCE && next == 0xBC)) {  // µ (micro), μ (mu)
      out += 'u';
      ++i;
    } else if (c == 0xC2 && next == 0xB7) {  // middle dot
      ++i;
    } else if (c == ' ' || c == '\t' || c == '*' || c == '.') {
      continue;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (out.ends_with("m3")) {
    out.pop_back();
    out += "^3";
  }
  return out;
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// "a length", "an ..." — the phrase used in "expected a pressure".
std::string with_article(Dimension d) {
  if (d == D::Dimensionless) return "a plain number";
  return "a " + dimension_name(d);
}

// Parses the longest number at the start of s; returns the characters used (0 if none).
std::size_t parse_leading_real(std::string_view s, double& value) {
  std::size_t skip = (!s.empty() && s[0] == '+') ? 1 : 0;
  // from_chars would take "+-1"; a sign after the '+' is not a number.
  if (skip && s.size() > 1 && s[1] == '-') return 0;
  const char* begin = s.data() + skip;
  const char* end = s.data() + s.size();
  const auto result = std::from_chars(begin, end, value, std::chars_format::general);
  if (result.ec != std::errc()) return 0;
  return static_cast<std::size_t>(result.ptr - s.data());
}

}  // namespace

std::string dimension_name(Dimension d) {
  switch (d) {
    case D::Dimensionless:
      return "dimensionless number";
    case D::Length:
      return "length";
    case D::Pressure:
      return "pressure";
    case D::Time:
      return "time";
    case D::Density:
      return "density";
    case D::Force:
      return "force";
    case D::ForcePerLength:
      return "force per length";
    case D::Moment:
      return "moment";
    case D::Voltage:
      return "voltage";
    case D::Frequency:
      return "frequency";
    case D::Mass:
      return "mass";
    case D::Temperature:
      return "temperature";
    case D::Velocity:
      return "velocity";
    case D::Viscosity:
      return "viscosity";
  }
  return "quantity";
}

std::string si_unit(Dimension d) {
  for (const auto& e : kUnits)
    if (e.unit.dimension == d && e.unit.factor == 1.0) return std::string(e.symbol);
  return "";
}

std::string example_units(Dimension d) {
  std::string out;
  for (const auto& e : kUnits) {
    if (e.unit.dimension != d) continue;
    if (!out.empty()) out += ", ";
    out += e.symbol;
  }
  return out;
}

const Unit* find_unit(std::string_view symbol) {
  const std::string key = normalise_symbol(symbol);
  for (const auto& e : kUnits)
    if (normalise_symbol(e.symbol) == key) return &e.unit;
  return nullptr;
}

bool parse_real(std::string_view text, double& value) {
  text = trim(text);
  if (text.empty()) return false;
  double v = 0.0;
  if (parse_leading_real(text, v) != text.size() || !std::isfinite(v)) return false;
  value = v;
  return true;
}

double parse_quantity(std::string_view text, Dimension expected) {
  text = trim(text);
  double number = 0.0;
  const std::size_t used = parse_leading_real(text, number);
  if (used == 0 || !std::isfinite(number)) {
    if (expected == D::Dimensionless) throw std::invalid_argument("expected a number");
    throw std::invalid_argument("expected " + with_article(expected) +
                                ", a number with an optional unit (" + example_units(expected) +
                                ")");
  }
  const std::string_view symbol = trim(text.substr(used));
  if (symbol.empty()) return number;  // SI

  const Unit* unit = find_unit(symbol);
  if (unit == nullptr) {
    if (expected == D::Dimensionless)
      throw std::invalid_argument("unknown unit '" + std::string(symbol) +
                                  "' (expected a plain number)");
    throw std::invalid_argument("unknown unit '" + std::string(symbol) + "' (expected " +
                                with_article(expected) + ": " + example_units(expected) + ")");
  }
  if (unit->dimension != expected) {
    std::string what = "unit '" + std::string(symbol) + "' is " + with_article(unit->dimension) +
                       ", expected " + with_article(expected);
    if (expected != D::Dimensionless) what += " (" + example_units(expected) + ")";
    throw std::invalid_argument(what);
  }
  return number * unit->factor;
}

}  // namespace rfmems
