"""A subcommand for the tests: it computes something numpy warns about, and prints it."""

import argparse

import numpy as np


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true")


def run(args: argparse.Namespace) -> int:
    with np.errstate(all="warn"):
        value = float(np.log(np.float64(0.0)))  # divide by zero: a RuntimeWarning, -inf
    print(value)
    return 0
