"""A results directory (cbbg run --out DIR, cbbg.main(["run", ...])) as Python objects.

    results = cbbg.load_results("results/exp1")
    results.summary["arms"]["cbbg"]["median"]
    results.trials["failed"]                    # a NumPy array per column
    results.table("trials", arm="bg_only")      # the rows of one arm
"""

import csv
import json
import os

import numpy as np


def _column(values):
    """A CSV column as a NumPy array: numbers where every value is one, else text."""
    try:
        return np.array([float(v) for v in values])
    except ValueError:
        return np.array(values, dtype=object)


def _read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}
    header, body = rows[0], rows[1:]
    return {name: _column([row[i] for row in body]) for i, name in enumerate(header)}


class Results:
    """What a finished results directory holds: summary.json as a dict, and each CSV table
    (trials, evaluation, figures, when there) as {column: NumPy array}."""

    TABLES = ("trials", "evaluation", "figures")

    def __init__(self, directory):
        self.directory = os.fspath(directory)
        if not os.path.isfile(os.path.join(self.directory, ".cbbg-results")):
            raise ValueError(
                f"'{self.directory}' is not a finished cbbg results directory (no .cbbg-results)"
            )
        with open(os.path.join(self.directory, "summary.json")) as f:
            self.summary = json.load(f)
        self.tables = {}
        for name in self.TABLES:
            path = os.path.join(self.directory, f"{name}.csv")
            if os.path.isfile(path):
                self.tables[name] = _read_csv(path)

    def __getattr__(self, name):
        tables = self.__dict__.get("tables", {})
        if name in tables:
            return tables[name]
        raise AttributeError(name)

    def table(self, name, arm=None):
        """The table `name`, or the rows of one arm."""
        table = self.tables[name]
        if arm is None:
            return table
        keep = table["arm"] == arm
        return {column: values[keep] for column, values in table.items()}


def load_results(directory):
    """The results directory `directory` (see Results)."""
    return Results(directory)
