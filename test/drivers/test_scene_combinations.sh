#!/usr/bin/env bash
# rfmems-pullin over the table of what a switch scene can combine: every supported cell runs
# on a small scene and asserts its physics, every unsupported one is bad input naming what is
# allowed (scene_combinations.py says what and how).
#
# Usage: bash test_scene_combinations.sh <directory of rfmems-pullin> <source directory>
set -uo pipefail
exec /usr/bin/python3 "$2/test/drivers/scene_combinations.py" "$1" "$2"
