"""What the plot scripts in this folder share: their command line, the opening of a result file,
the finishing and writing of a figure, and the bad-input contract.

The contract, as the drivers': a missing or unreadable input file ends the script with one line
on stderr, "<script>: <the error, naming the file>", and exit code 2, not a traceback
(test/drivers/test_plot_scripts.sh).
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402


def run_main(main):
    """Runs a script's main; an OSError (a missing or unreadable file) is bad input."""
    try:
        main()
    except OSError as e:
        print(f"{sys.argv[0].rsplit('/', 1)[-1]}: {e}", file=sys.stderr)
        sys.exit(2)


def prefix_args(description, several=False):
    """The command line RESULT.h5 [-o PREFIX] (several: RESULT.h5 [RESULT.h5 ...] [-o PREFIX]),
    and the prefix of the figures: the given one, else the (first) result without .h5."""
    parser = argparse.ArgumentParser(description=description)
    if several:
        parser.add_argument("results", nargs="+", help="result files (.h5)")
        parser.add_argument("-o", "--prefix",
                            help="output prefix (default: first RESULT without .h5)")
    else:
        parser.add_argument("result", help="result file (.h5)")
        parser.add_argument("-o", "--prefix", help="output prefix (default: RESULT without .h5)")
    args = parser.parse_args()
    first = args.results[0] if several else args.result
    return args, args.prefix or os.path.splitext(first)[0]


def open_result(path):
    """The HDF5 result file at path, open for reading; failing, an OSError that names it."""
    try:
        return h5py.File(path, "r")
    except OSError as e:
        raise OSError(f"{path}: {e}") from e


def save(fig, path, dpi=150):
    """fig laid out, written to path and closed; returns path."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def finish(fig, ax, xlabel, ylabel, path, dpi=150, **legend):
    """A one-panel figure's axis labels, light grid and legend (legend: its keywords), then
    save(fig, path, dpi); returns path."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(**legend)
    return save(fig, path, dpi)
