#include "materials/flow_factor_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/error.hpp"

namespace rfmems {

namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    const auto a = cell.find_first_not_of(" \t\r");
    const auto b = cell.find_last_not_of(" \t\r");
    out.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  return out;
}

// Fritsch-Butland slope at an interior node from the secants d0 (left) and d1 (right) over
// intervals h0 and h1: a weighted harmonic mean, zero where the data turn.
Real interior_slope(Real h0, Real h1, Real d0, Real d1) {
  if (d0 * d1 <= 0) return 0;
  const Real w0 = 2 * h1 + h0, w1 = h1 + 2 * h0;
  return (w0 + w1) / (w0 / d0 + w1 / d1);
}

}  // namespace

FlowFactorTable::FlowFactorTable(std::vector<Real> knudsen, std::vector<Real> flow_factor,
                                 std::string source)
    : kn_(std::move(knudsen)), q_(std::move(flow_factor)), source_(std::move(source)) {
  const std::size_t n = kn_.size();
  if (n < 2 || q_.size() != n)
    throw InputError(fmt::format("{}: a flow-factor table needs at least two (Kn, Q) rows, has {}",
                                 source_, std::min(n, q_.size())));
  for (std::size_t i = 0; i < n; ++i) {
    if (!(kn_[i] > 0) || !(q_[i] > 1) || !std::isfinite(kn_[i]) || !std::isfinite(q_[i]))
      throw InputError(fmt::format("{}: row {} (Kn = {:g}, Q = {:g}): expected Kn > 0 and Q > 1",
                                   source_, i + 1, kn_[i], q_[i]));
    if (i > 0 && !(kn_[i] > kn_[i - 1] && q_[i] > q_[i - 1]))
      throw InputError(fmt::format(
          "{}: row {} (Kn = {:g}, Q = {:g}): Kn and Q must increase strictly down the table",
          source_, i + 1, kn_[i], q_[i]));
  }
  x_.resize(n);
  y_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    x_[i] = std::log(kn_[i]);
    y_[i] = std::log(q_[i]);
  }
  slope_.resize(n);
  auto secant = [&](std::size_t i) { return (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]); };
  slope_[0] = secant(0);
  slope_[n - 1] = secant(n - 2);
  for (std::size_t i = 1; i + 1 < n; ++i)
    slope_[i] = interior_slope(x_[i] - x_[i - 1], x_[i + 1] - x_[i], secant(i - 1), secant(i));

  const Real root_pi = std::sqrt(std::numbers::pi);
  auto g = [&](std::size_t i) { return root_pi * q_[i] / (12 * kn_[i]); };
  const Real last_slope = (g(n - 1) - g(n - 2)) / (x_[n - 1] - x_[n - 2]);
  fm_slope_ = (last_slope + 1 / root_pi) / 2;
  const Real bound = std::abs(1 / root_pi - last_slope) / 2;
  const Real log_reach = bound > 0 ? kExtrapolationError * g(n - 1) / bound : HUGE_VAL;
  max_extrapolated_ = kn_.back() * std::exp(std::min(log_reach, std::log(kMaxReach)));
}

FlowFactorTable FlowFactorTable::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read the flow-factor table", path));
  std::string line;
  int line_number = 0, kn_column = -1, q_column = -1;
  std::size_t n_columns = 0;
  std::vector<Real> kn, q;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    const std::vector<std::string> cells = split_csv(line);
    if (kn_column < 0) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i] == "knudsen") kn_column = static_cast<int>(i);
        if (cells[i] == "flow_factor") q_column = static_cast<int>(i);
      }
      if (kn_column < 0 || q_column < 0)
        throw InputError(
            fmt::format("{}:{}: the header must name the columns 'knudsen' and 'flow_factor'", path,
                        line_number));
      n_columns = cells.size();
      continue;
    }
    if (cells.size() != n_columns)
      throw InputError(fmt::format("{}:{}: {} values, the header has {}", path, line_number,
                                   cells.size(), n_columns));
    for (int column : {kn_column, q_column}) {
      const std::string& text = cells[column];
      std::size_t used = 0;
      Real value = 0;
      try {
        value = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != text.size())
        throw InputError(fmt::format("{}:{}: '{}' is not a number", path, line_number, text));
      (column == kn_column ? kn : q).push_back(value);
    }
  }
  if (kn_column < 0)
    throw InputError(fmt::format("{}: no header line (columns knudsen, flow_factor)", path));
  return FlowFactorTable(std::move(kn), std::move(q), path);
}

FlowFactorTable::Value FlowFactorTable::evaluate(Real kn) const {
  const std::size_t n = kn_.size();
  if (!(kn > 0)) throw InputError(fmt::format("{}: flow factor asked at Kn = {:g}", source_, kn));
  if (kn < kn_.front()) {
    const Real s = (q_.front() - 1) / kn_.front();
    return {1 + s * kn, s};
  }
  if (kn > kn_.back()) {
    if (kn > max_extrapolated_knudsen())
      throw InputError(fmt::format(
          "{}: Kn = {:.4g} is beyond the flow-factor table's free-molecular extrapolation (up to "
          "Kn = {:.4g}, its largest Kn {:g}); extend the table (rfmems-flow-factor)",
          source_, kn, max_extrapolated_, kn_.back()));
    const Real root_pi = std::sqrt(std::numbers::pi);
    const Real g = root_pi * q_.back() / (12 * kn_.back()) + fm_slope_ * std::log(kn / kn_.back());
    return {12 * kn * g / root_pi, 12 * (g + fm_slope_) / root_pi};
  }
  const Real x = std::log(kn);
  const std::size_t i =
      std::min<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin(), n - 1) - 1;
  const Real h = x_[i + 1] - x_[i], t = (x - x_[i]) / h;
  // Cubic Hermite basis on [0, 1] and its derivative.
  const Real h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  const Real h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  const Real d00 = 6 * t * (t - 1), d10 = (1 - t) * (1 - 3 * t);
  const Real d01 = -d00, d11 = t * (3 * t - 2);
  const Real y = h00 * y_[i] + h * h10 * slope_[i] + h01 * y_[i + 1] + h * h11 * slope_[i + 1];
  const Real dy_dx = (d00 * y_[i] + d01 * y_[i + 1]) / h + d10 * slope_[i] + d11 * slope_[i + 1];
  const Real q = std::exp(y);
  return {q, q / kn * dy_dx};
}

}  // namespace rfmems
