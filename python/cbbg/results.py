"""A results directory (cbbg run --out DIR, cbbg.main(["run", ...])) as Python objects.

    results = cbbg.load_results("results/exp1")
    results.summary["arms"]["cbbg"]["median"]
    results.trials["failed"]                    # a NumPy array per column, typed
    results.table("trials", arm="bg_only")      # the rows of one arm
    results.schema["figures"]                   # what the protocol's results hold
    results.config["plant.kind"]                # the config the run recorded
    results.steps(arm="cbbg", seed=1, trial=1)  # steps.csv's rows, read when asked

Columns are typed by the results' schema (schema.json): integers as int64, numbers as float64
(NaN where a cell is "nan"), flags as bool, text as str; a flag or integer column with empty
cells (a seed or trial without a value) is float64 with NaN there. Results written before
schema.json are typed by what their cells hold.
"""

import csv
import json
import os

import numpy as np

from . import _cbbg

# The columns every results file has, beyond the protocol's own (schema.json).
_TRIAL_COLUMNS = {"arm": "text", "seed": "integer", "trial": "integer", "failed": "flag",
                  "steps": "integer", "mean_temperature": "number", "mean_entropy": "number",
                  "final_theta": "number", "status": "text"}
_EVALUATION_COLUMNS = {"arm": "text", "seed": "integer", "theta0": "number",
                       "balanced": "flag", "steps": "integer", "final_theta": "number",
                       "status": "text"}
_SEED_COLUMNS = {"arm": "text", "seed": "integer"}


def _inferred(values):
    """A column without a declared type: numbers where every value is one, else text."""
    try:
        return np.array([float(v) for v in values])
    except ValueError:
        return np.array(values, dtype=object)


def _typed(values, kind):
    """A CSV column of the declared kind (integer, number, flag, text) as a NumPy array."""
    if kind == "text":
        return np.array(values, dtype=object)
    if kind == "number" or any(v == "" for v in values):
        return np.array([float(v) if v != "" else np.nan for v in values])
    if kind == "flag":
        return np.array([v == "1" for v in values], dtype=bool)
    return np.array([int(v) for v in values], dtype=np.int64)


def _read_csv(path, kinds):
    """{column: array}; `kinds` maps column names to their declared kind."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}
    header, body = rows[0], rows[1:]
    table = {}
    for i, name in enumerate(header):
        values = [row[i] for row in body]
        kind = kinds.get(name)
        table[name] = _typed(values, kind) if kind else _inferred(values)
    return table


class Results:
    """What a finished results directory holds: summary.json and schema.json as dicts, the
    recorded config, and each CSV table (trials, evaluation, figures, when there) as {column:
    NumPy array}; steps.csv is read when asked (steps())."""

    TABLES = ("trials", "evaluation", "figures")

    def __init__(self, directory, _finished_by_sweep=False):
        if not isinstance(directory, (str, os.PathLike)):
            raise TypeError("load_results: the directory is a path (str or os.PathLike); got "
                            f"{type(directory).__name__} {directory!r}")
        self.directory = os.fspath(directory)
        # A sweep's points are finished when the sweep is (its own .cbbg-results).
        if not _finished_by_sweep and not os.path.isfile(
                os.path.join(self.directory, ".cbbg-results")):
            raise ValueError(
                f"'{self.directory}' is not a finished cbbg results directory (no .cbbg-results)"
            )
        self.summary = self._json("summary.json")
        self.schema = self._json("schema.json") if self._has("schema.json") else None
        kinds = self._column_kinds()
        self.tables = {}
        for name in self.TABLES:
            if self._has(f"{name}.csv"):
                self.tables[name] = _read_csv(self._path(f"{name}.csv"), kinds[name])

    @property
    def config(self):
        """The config the run recorded (config.yaml) as a cbbg.Config: config["plant.kind"].
        Read when asked: a key of a section the run registered needs that section registered
        here too."""
        config = _cbbg.Config()
        config.merge_file(self._path("config.yaml"))
        return config

    def _path(self, name):
        return os.path.join(self.directory, name)

    def _has(self, name):
        return os.path.isfile(self._path(name))

    def _json(self, name):
        with open(self._path(name)) as f:
            return json.load(f)

    def _column_kinds(self):
        """Per table, {column: kind} from the schema (nothing declared without one)."""
        if self.schema is None:
            return {name: {} for name in self.TABLES}
        trials = dict(_TRIAL_COLUMNS)
        trials.update({c["name"]: c["type"] for c in self.schema.get("trial_columns", [])})
        figures = dict(_SEED_COLUMNS)
        figures.update({f["name"]: f["type"] for f in self.schema.get("figures", [])})
        return {"trials": trials, "evaluation": dict(_EVALUATION_COLUMNS), "figures": figures}

    def __getattr__(self, name):
        tables = self.__dict__.get("tables", {})
        if name in tables:
            return tables[name]
        raise AttributeError(name)

    def __repr__(self):
        arms = list(self.summary.get("arms", {}))
        return (f"Results('{self.directory}': {self.summary.get('experiment')}, arms {arms}, "
                f"{len(self.summary.get('seeds', []))} seed(s))")

    def table(self, name, arm=None):
        """The table `name`, or the rows of one arm."""
        table = self.tables[name]
        if arm is None:
            return table
        keep = table["arm"] == arm
        return {column: values[keep] for column, values in table.items()}

    def steps(self, arm=None, seed=None, trial=None):
        """steps.csv's rows (those of `arm`, `seed` and `trial` where given) as {column:
        array}: arm as str, seed and trial as int64, every signal as float64. ValueError when
        the run logged no ticks (log.decimation 0)."""
        path = self._path("steps.csv")
        if not os.path.isfile(path):
            raise ValueError(f"'{self.directory}' has no steps.csv (the run logged no ticks)")
        wanted = (arm, None if seed is None else str(seed), None if trial is None else str(trial))
        with open(path, newline="") as f:
            reader = csv.reader(f)
            header = next(reader)
            rows = [row for row in reader
                    if all(w is None or row[i] == w for i, w in enumerate(wanted))]
        columns = {}
        for i, name in enumerate(header):
            values = [row[i] for row in rows]
            kind = {"arm": "text", "seed": "integer", "trial": "integer"}.get(name, "number")
            columns[name] = _typed(values, kind)
        return columns


def load_results(directory):
    """The results directory `directory` (see Results)."""
    return Results(directory)


def _column(values):
    """Values of one sweep column: int64, bool or float64 (NaN where a value is missing) when
    they are all of one kind of number, else str."""
    present = [v for v in values if v is not None]
    if all(isinstance(v, (bool, np.bool_)) for v in present) and len(present) == len(values):
        return np.array(values, dtype=bool)
    if all(isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))
           for v in present) and len(present) == len(values):
        return np.array(values, dtype=np.int64)
    try:
        return np.array([np.nan if v is None else float(v) for v in values])
    except (TypeError, ValueError):
        return np.array(values, dtype=object)


def load_sweep(directory):
    """A finished sweep (cbbg run --grid ... --out DIR, its shards merged) as one table: a row
    per grid point, arm and seed, as {column: NumPy array}, so pandas.DataFrame(load_sweep(DIR))
    is its frame. Columns: point; each grid key's value (float64 where every value is a number,
    else str); arm; seed; failures_before_success and succeeded (every protocol's); then the
    protocol's per-seed figures (figures.csv: transfer's balanced@C and evaluated@C,
    trials_to_skill, ...), NaN where a seed has none."""
    if not isinstance(directory, (str, os.PathLike)):
        raise TypeError("load_sweep: the directory is a path (str or os.PathLike); got "
                        f"{type(directory).__name__} {directory!r}")
    directory = os.fspath(directory)
    sweep_csv = os.path.join(directory, "sweep.csv")
    if not (os.path.isfile(os.path.join(directory, ".cbbg-results"))
            and os.path.isfile(sweep_csv)):
        raise ValueError(f"'{directory}' is not a finished cbbg sweep (no sweep.csv and "
                         ".cbbg-results; merge its shards with cbbg merge)")
    with open(sweep_csv, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        points = list(reader)
    keys = header[1:header.index("arm")]
    rows = []
    for point in points:
        fields = dict(zip(header, point))
        results = Results(os.path.join(directory, "points", fields["point"]),
                          _finished_by_sweep=True)
        rows.extend(_seed_rows(results, fields, keys))
    names = list(dict.fromkeys(name for row in rows for name in row))
    table = {name: _column([row.get(name) for row in rows]) for name in names}
    for key in keys:  # a grid key's values as the sweep wrote them: numbers, or text
        table[key] = _inferred([str(v) for v in table[key]]) if len(rows) else table[key]
    return table


def _seed_rows(results, fields, keys):
    """The rows of one grid point and arm (sweep.csv's `fields`), one per seed."""
    arm = fields["arm"]
    summary = results.summary["arms"][arm]
    figures = results.tables.get("figures", {})
    by_seed = {}
    if figures:
        for i, (row_arm, seed) in enumerate(zip(figures["arm"], figures["seed"])):
            if row_arm == arm:
                by_seed[int(seed)] = {name: figures[name][i].item()
                                      for name in figures if name not in ("arm", "seed")}
    rows = []
    for i, seed in enumerate(results.summary["seeds"]):
        row = {"point": int(fields["point"])}
        row.update({key: fields[key] for key in keys})
        row.update({"arm": arm, "seed": seed,
                    "failures_before_success": summary["failures_before_success"][i],
                    "succeeded": summary["succeeded"][i]})
        for name, value in by_seed.get(seed, {}).items():
            row[name] = None if isinstance(value, float) and np.isnan(value) else value
        rows.append(row)
    return rows
