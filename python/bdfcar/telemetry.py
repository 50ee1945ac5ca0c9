"""A run's telemetry: the CSV's columns (docs/TELEMETRY.md) as one NumPy array."""


class Telemetry:
    """Rows x columns of float64, named as the CSV header; t["yawrate_radps"] is a column."""

    def __init__(self, result):
        self.columns = list(result["columns"])
        self.data = result["data"]
        self.ok = bool(result["ok"])
        self.failure = result["failure"]
        self.failure_time = result["failure_time"]
        self.steps = int(result["steps"])
        self.wall_seconds = result["wall_seconds"]
        self.simulated_seconds = result["simulated_seconds"]
        self.course_passed = result.get("course_passed")
        self.cone_hits = result.get("cone_hits")
        self._index = {name: i for i, name in enumerate(self.columns)}

    def __getitem__(self, name):
        try:
            return self.data[:, self._index[name]]
        except KeyError:
            raise KeyError(f"no telemetry column {name!r}; the columns are {', '.join(self.columns)}") from None

    def __len__(self):
        return self.data.shape[0]

    def __repr__(self):
        state = "ok" if self.ok else f"failed: {self.failure}"
        return f"<Telemetry {len(self)} rows x {len(self.columns)} columns, {state}>"

    def to_csv_rows(self):
        """The rows as the CSV prints them (10 significant digits; whole-number columns as integers;
        newton_correction with 4): the same text as the file of `bdfcar run`."""
        fmt = []
        for name in self.columns:
            if name in ("newton_iterations", "segment", "fidelity", "gear"):
                fmt.append(lambda v: str(int(v)))
            elif name == "newton_correction":
                fmt.append(lambda v: _general(v, 4))
            else:
                fmt.append(lambda v: _general(v, 10))
        return [",".join(f(v) for f, v in zip(fmt, row)) for row in self.data.tolist()]


def _general(v, digits):
    """printf's %.Ng (what the CSV writer prints: std::to_chars general with that precision)."""
    return "%.*g" % (digits, v)

