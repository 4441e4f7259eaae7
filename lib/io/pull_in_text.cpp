#include "io/pull_in_text.hpp"

#include <fmt/format.h>

namespace rfmems {

namespace {

double um(const Json& metres) { return 1e6 * metres.get<double>(); }

// A free response worth printing: fitted, and over at least one damped period of the history.
bool measured(const Json& response, double duration) {
  return response.value("fitted", false) && duration * response.value("frequency", 0.0) >= 1.0;
}

// What the run at a fraction of the tolerances says of the reported pull-in time.
std::string time_check_note(const Json& dynamic) {
  if (!dynamic.contains("pull_in_time_check")) return "";
  const Json& c = dynamic["pull_in_time_check"];
  const double factor = c["tolerance_factor"].get<double>();
  if (c["relative_error_estimate"].is_null())
    return fmt::format(
        " (at {:g} x the tolerances this voltage does not pull in: it is within "
        "the integration error of V_dyn)",
        factor);
  return fmt::format(" ({:.2g} % from a run at {:g} x the tolerances: {:.3f} us)",
                     100 * c["relative_error_estimate"].get<double>(), factor,
                     um(c["pull_in_time"]));
}

std::string dynamic_lines(const Json& p) {
  const Json& d = p["dynamic"];
  const std::string time =
      d["pull_in_time"].is_null()
          ? std::string("no touch-down by end_time (past the unstable equilibrium)")
          : fmt::format("pull-in time {:.3f} us{}", um(d["pull_in_time"]), time_check_note(d));
  std::string out = fmt::format(
      "  dynamic pull-in ({} voltage, {}) at {:.2f} V ({:.3f} of quasi-static; {:.2f} V does "
      "not), {}; {} runs\n",
      d["waveform"].get<std::string>(), p["coupling"]["scheme"].get<std::string>(),
      d["pull_in_voltage"].get<double>(), d["ratio_to_quasi_static"].get<double>(),
      d["not_pulling_in"].get<double>(), time, d["runs"].get<int>());
  if (d.contains("small_signal") && d["small_signal"].value("fitted", false))
    out += fmt::format("  small signal at {:.2f} V: damping ratio {:.4g}, {:.4g} MHz\n",
                       d["small_signal"]["voltage"].get<double>(),
                       d["small_signal"]["damping_ratio"].get<double>(),
                       1e-6 * d["small_signal"]["frequency"].get<double>());
  if (!d.contains("release")) return out;
  const Json& r = d["release"];
  out += fmt::format(
      "  release: step to {:.2f} V, touch-down at {:.3f} us, drop to {:.2f} V at "
      "{:.3f} us: {}",
      r["voltage"].get<double>(), um(r["pull_in_time"]), r["hold_voltage"].get<double>(),
      um(r["drop_time"]), r["released"].get<bool>() ? "released" : "holds");
  if (r["released"].get<bool>()) out += fmt::format(" {:.3f} us later", um(r["release_time"]));
  out += "\n";
  if (r.contains("pull_out_voltage"))
    out += fmt::format(
        "  dynamic pull-out at {:.2f} V (holds; {:.2f} V releases, {:.3f} us "
        "after the drop); {} runs\n",
        r["pull_out_voltage"].get<double>(), r["releasing"].get<double>(),
        um(r["release_time_at_releasing"]), r["runs"].get<int>());
  return out;
}

// The harmonic response: the sweep, its peak and, with a film, its spring and damping at the
// sweep's ends.
std::string harmonic_lines(const Json& h) {
  const Json& f = h["frequencies"];
  const Json& amplitude = h["control"]["amplitude"];
  std::string out = fmt::format(
      "  harmonic about {:.2f} V (static control deflection {:.4f} um): {} frequencies {:.4g} .. "
      "{:.4g} Hz; control response {:.4g} nm/V at {:.4g} Hz, largest {:.4g} nm/V at {:.4g} Hz\n",
      h["bias"].get<double>(), um(h["static_control"]), f.size(), f.front().get<double>(),
      f.back().get<double>(), 1e9 * amplitude.front().get<double>(), f.front().get<double>(),
      1e9 * h["peak"]["amplitude"].get<double>(), h["peak"]["frequency"].get<double>());
  if (h.contains("film")) {
    const Json& film = h["film"];
    for (const std::size_t k : {std::size_t{0}, f.size() - 1})
      out += fmt::format("  film at {:.4g} Hz: spring {:.4g} N/m, damping {:.4g} N s/m\n",
                         f[k].get<double>(), film["spring"][k].get<double>(),
                         film["damping"][k].get<double>());
  }
  return out;
}

std::string transient_line(const std::string& head, const Json& p) {
  const Json& t = p["transient"];
  std::string out = fmt::format(
      "{}: {:.2f} V step ({}), control deflection {:.4f} um at {:.3f} us, extreme {:.4f} um", head,
      t["voltage"].get<double>(), p["coupling"]["scheme"].get<std::string>(),
      um(t["final_control"]), um(t["final_time"]), um(t["extreme_control"]));
  if (t["pulled_in"].get<bool>() && !t["pull_in_time"].is_null())
    out += fmt::format(", pull-in time {:.4f} us", um(t["pull_in_time"]));
  else if (t.contains("free_response") &&
           measured(t["free_response"], t["final_time"].get<double>()))
    out += fmt::format(", damping ratio {:.4g}", t["free_response"]["damping_ratio"].get<double>());
  out += fmt::format("; {} steps, {} residual evaluations", t["steps"].get<long>(),
                     t["residual_evals"].get<long>());
  const Json& c = p["counters"];
  if (c.contains("gas_steps") && c["gas_steps"].get<long>() > 0)
    out += fmt::format(", {} gas steps", c["gas_steps"].get<long>());
  if (c.contains("coupling_iterations") && c["coupling_iterations"].get<long>() > 0)
    out += fmt::format(", {} coupling iterations", c["coupling_iterations"].get<long>());
  return out + "\n";
}

}  // namespace

std::string pull_in_text(const std::string& name, const Json& p) {
  const std::string head =
      fmt::format("{} ({}, {}, gas {})", name, p["structure"].get<std::string>(),
                  p["electrostatics"].get<std::string>(), p["gas"].get<std::string>());
  if (p.contains("transient")) return transient_line(head, p);
  if (p.contains("static"))
    return fmt::format("{}: static at {:.1f} V, control deflection {:.5f} um\n", head,
                       p["static"]["voltage"].get<double>(), um(p["static"]["control"]));
  const Json& qs = p["quasi_static"];
  std::string out = fmt::format(
      "{}: quasi-static pull-in at {:.2f} V, control deflection {:.3f} um ({:.1f} % of the "
      "gap)\n",
      head, qs["pull_in_voltage"].get<double>(), um(qs["pull_in_displacement"]),
      100 * qs["pull_in_fraction_of_gap"].get<double>());
  if (qs.contains("modes")) {
    // The first frequency at rest and at the last stable state before the fold.
    const Json& first = qs["modes"].front();
    const Json& last = qs["modes"].back();
    out += fmt::format(
        "  first frequency {:.4g} Hz at rest, {:.4g} Hz at {:.2f} V ({} states, {} modes each)\n",
        first["frequencies"][0].get<double>(), last["frequencies"][0].get<double>(),
        last["voltage"].get<double>(), qs["modes"].size(), first["frequencies"].size());
  }
  if (qs.contains("pull_out"))
    out += fmt::format(
        "  quasi-static pull-out at {:.2f} V (resting on the dielectric over {:.1f} "
        "% of the electrode just above it)\n",
        qs["pull_out"]["voltage"].get<double>(),
        100 * qs["pull_out"]["contact_fraction"].get<double>());
  if (p.contains("harmonic")) out += harmonic_lines(p["harmonic"]);
  if (p.contains("dynamic")) out += dynamic_lines(p);
  return out;
}

}  // namespace rfmems
