#!/usr/bin/env bash
# rfmems-pullin's harmonic analysis (coupling/harmonic_under_bias.hpp) on the squeeze-film
# switch (cases/switch_plate_damped, coarsened to 20 x 6 cells): the response to a small AC
# voltage about a DC bias, and the film's spring and damping against frequency.
#   - At 1 Hz the response per AC volt is the static sensitivity d(control)/dV, which two static
#     equilibria 0.01 V either side of the bias give by central differences (to 1e-5).
#   - The film: at small squeeze numbers a damper, k_film growing as f^2 and c_film constant;
#     at large ones an isothermal gas spring with no time to flow, k_film -> p_a A / g0 (the
#     plate's 400 x 120 um over 2 um at 1 atm: 2431.8 N/m; at 5 V the bias deflects the plate by
#     0.08 % of the gap, so to 1e-3), its damping vanishing.
#   - The result file's /pull_in/harmonic, the plot, and bad input.
# The 1-DOF actuator's closed form: test/unit/coupling/test_harmonic_bias.cpp.
#
# Usage: bash test_pullin_harmonic.sh <directory of rfmems-pullin> <source directory>
set -uo pipefail

DRIVER="$1/rfmems-pullin"
SRC="$2"
CASE="$SRC/cases/switch_plate_damped/case.yaml"
COARSE=(--set "mesh.cells=[20, 6]" --set pull_in.mode=harmonic)

source "$SRC/test/drivers/common.sh"

harmonic() {  # NAME BIAS FREQUENCIES
  expect_json_run "$1" "harmonic about $2" "$CASE" "${COARSE[@]}" \
    --set "pull_in.harmonic={bias: $2, frequencies: [$3]}"
}
harmonic low "5 V" "100 Hz, 200 Hz, 10 GHz"
for v in 39.99 40 40.01; do harmonic "b$v" "$v V" "1 Hz, 100 kHz, 1 MHz"; done

if $PY - "$WORK" <<'PY'
import json, math, sys
work = sys.argv[1]
def harmonic(name):
    return json.load(open(f"{work}/{name}.json"))["pull_in"]["harmonic"]
low = harmonic("low")
film = low["film"]
k, c = film["spring"], film["damping"]
limit = 101325 * 400e-6 * 120e-6 / 2e-6
print(f"film: k(100 Hz) = {k[0]:.6e}, k(200 Hz) / k(100 Hz) = {k[1] / k[0]:.6f}, "
      f"c(200 Hz) / c(100 Hz) - 1 = {c[1] / c[0] - 1:.2e}; k(10 GHz) = {k[2]:.3f} N/m "
      f"(p_a A / g0 = {limit:.3f}, {k[2] / limit - 1:+.2e}), c(10 GHz) = {c[2]:.2e}")
assert abs(k[1] / k[0] - 4) < 1e-4, k                    # a damper: k ~ f^2
assert abs(c[1] / c[0] - 1) < 1e-5 and c[0] > 0, c      # ... c constant
assert 0 < k[2] / limit - 1 < 1e-3, (k[2], limit)        # a gas spring, a little stiffer
assert abs(c[2]) * 2 * math.pi * 1e10 < 1e-9 * k[2], c   # ... without damping
assert low["factorizations"] == 1 and low["refactorizations"] == 2, low

plus, mid, minus = harmonic("b40.01"), harmonic("b40"), harmonic("b39.99")
slope = (plus["static_control"] - minus["static_control"]) / 0.02
amplitude, phase = mid["control"]["amplitude"][0], mid["control"]["phase_deg"][0]
print(f"d(control)/dV = {slope:.8e} m/V by differences; harmonic at 1 Hz {amplitude:.8e} m/V, "
      f"phase {phase:.4f} deg ({amplitude / abs(slope) - 1:+.1e})")
assert abs(amplitude / abs(slope) - 1) < 1e-5, (amplitude, slope)
assert slope < 0 and abs(abs(phase) - 180) < 0.01, phase  # closing as the voltage rises
assert mid["control"]["units"] == "m/V" and mid["peak"]["frequency"] > 0, mid
PY
then pass "harmonic: static limit, damper and gas-spring limits"; else fail "harmonic limits"; fi

if $PY - "$WORK/b40.h5" <<'PY'
import h5py, sys
with h5py.File(sys.argv[1]) as f:
    g = f["pull_in/harmonic"]
    names = [n.decode() if isinstance(n, bytes) else n for n in g["values"].attrs["components"]]
    assert names == ["control_real", "control_imag", "film_force_real", "film_force_imag",
                     "film_spring", "film_damping"], names
    assert g["values"].shape == (3, 6) and list(g["frequency"][()]) == [1.0, 1e5, 1e6]
    assert "pull_in/curve" in f and "fields" in f
PY
then pass "result file: /pull_in/harmonic"; else fail "result file: /pull_in/harmonic"; fi
if $PY "$SRC/python/plot_pullin.py" "$WORK/b40.h5" -o "$WORK/plot" >/dev/null &&
   [ -s "$WORK/plot_harmonic.png" ]; then
  pass "plot_pullin.py draws the harmonic response"
else
  fail "plot_pullin.py on a harmonic result"
fi

expect_input_error bias_above_fold "pull_in.harmonic.bias' = '90 V': not below the quasi-static" \
  "$CASE" "${COARSE[@]}" --set "pull_in.harmonic={bias: 90 V, frequencies: [1 kHz]}"
expect_input_error no_bias "missing key 'pull_in.harmonic.bias'" \
  "$CASE" "${COARSE[@]}" --set "pull_in.harmonic={frequencies: [1 kHz]}"
expect_input_error both_lists "one of the two" "$CASE" "${COARSE[@]}" \
  --set "pull_in.harmonic={bias: 40 V, frequencies: [1 kHz], sweep: {from: 1 kHz, to: 2 kHz}}"
expect_input_error laplace_harmonic "allowed: static | quasi_static | dynamic | transient" \
  "$SRC/cases/switch_plane_laplace/case.yaml" --set pull_in.mode=harmonic

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
