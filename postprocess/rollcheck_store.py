"""Reading a rollcheck results store (HDF5, layout "rollcheck-results-1").

The layout is documented in src/io/results_store.h: /cases/<name>/ per
case, with the record's fields as attributes, the resolved parameters as
attributes of ./parameters, the scene's JSON summary mapped to groups and
datasets under ./summary (each numeric dataset with its declared "units", a
table with its "columns"), and the case's output files in ./files.

Run with Debian's interpreter, /usr/bin/python3 (matplotlib, h5py).
"""
from dataclasses import dataclass, field

import h5py
import numpy as np


@dataclass
class Case:
    name: str
    attrs: dict                                   # status, kind, wall_s, hash, message, ...
    parameters: dict                              # resolved parameters of the case file
    summary: dict = field(default_factory=dict)   # the scene's JSON summary, as numpy values
    files: list = field(default_factory=list)     # paths relative to the store's folder
    units: dict = field(default_factory=dict)     # summary path ("sliding/max_speed_m_s") -> its unit ("m/s")
    columns: dict = field(default_factory=dict)   # a table's path ("convergence/cds") -> its column names

    @property
    def kind(self):
        return self.attrs.get("kind", "")

    @property
    def ok(self):
        return self.attrs.get("status") == "ok"


def _value(x):
    """An HDF5 value as plain Python/numpy: str for strings, None for an empty dataspace."""
    if isinstance(x, h5py.Empty):
        return None
    if isinstance(x, bytes):
        return x.decode("utf-8")
    if isinstance(x, np.ndarray) and x.dtype.kind == "O":
        return [v.decode("utf-8") if isinstance(v, bytes) else v for v in x.tolist()]
    if isinstance(x, np.generic):
        return x.item()
    return x


def _attrs(obj):
    return {k: _value(v) for k, v in obj.attrs.items()}


def _tree(group):
    """A summary group as the JSON it came from: dicts, lists (json_array groups), numpy arrays, scalars."""
    out = {}
    for key, item in group.items():
        if isinstance(item, h5py.Group):
            out[key] = _tree(item)
        else:
            out[key] = _value(item[()])
    if group.attrs.get("json_array", 0) == 1:
        return [out[k] for k in sorted(out, key=int)]
    return out


def _field_attributes(group):
    """The declared unit of every numeric dataset under a summary group and the column names of its tables."""
    units, columns = {}, {}

    def visit(name, item):
        if isinstance(item, h5py.Dataset):
            if "units" in item.attrs:
                units[name] = _value(item.attrs["units"])
            if "columns" in item.attrs:
                columns[name] = _value(item.attrs["columns"]).split(", ")
    group.visititems(visit)
    return units, columns


def load_cases(path):
    """Every case of the store, in the batch's order, and the store's root attributes."""
    with h5py.File(path, "r") as f:
        root = _attrs(f)
        cases = []
        # /cases tracks creation order, so h5py lists the cases in the batch's order.
        for name, g in f["cases"].items():
            units, columns = _field_attributes(g["summary"]) if "summary" in g else ({}, {})
            cases.append(Case(
                name=name,
                attrs=_attrs(g),
                parameters=_attrs(g["parameters"]) if "parameters" in g else {},
                summary=_tree(g["summary"]) if "summary" in g else {},
                files=_value(g["files"][()]) if "files" in g else [],
                units=units,
                columns=columns,
            ))
    return root, cases


def label(case, keys=("body", "model", "degree", "oracle")):
    """A short label: the case name and its distinguishing parameters."""
    parts = [f"{k}={case.parameters[k]}" for k in keys
             if k in case.parameters and case.parameters[k] not in ("", None)]
    return case.name + (f" ({', '.join(parts)})" if parts else "")


class Skip(Exception):
    """A plot that the store holds no data for; the message says which data it needs."""


class MissingKey(LookupError):
    """A key the output contract promises is not in a record: the store and the scripts disagree."""


def require(record, key, where):
    """record[key]; MissingKey naming the key and `where` it was looked for (a case, a file) when it is missing."""
    if not isinstance(record, dict) or key not in record:
        raise MissingKey(f"{where}: no key '{key}'")
    return record[key]


@dataclass
class Figure:
    """A drawn plot: its PNG (in the output folder), what it shows, and what to conclude from it."""
    png: str
    title: str
    shows: str
    conclusion: str


def count(n, noun, plural=None):
    """'1 case', '3 cases', '2 bodies' (with plural='bodies')."""
    return f"{n} {noun if n == 1 else plural or noun + 's'}"


def percent(x):
    """A relative quantity as a percentage with two significant digits: 0.00123 -> '0.12 %'."""
    return f"{100 * x:.2g} %"


def is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def run_standalone(draw):
    """`script.py STORE OUT_DIR`: draws one plot module's figures into OUT_DIR."""
    import os
    import sys
    if len(sys.argv) != 3:
        sys.exit(f"usage: {sys.argv[0]} STORE OUT_DIR")
    _, cases = load_cases(sys.argv[1])
    os.makedirs(sys.argv[2], exist_ok=True)
    try:
        for figure in draw(cases, sys.argv[2]):
            print(f"{os.path.join(sys.argv[2], figure.png)}: {figure.shows} {figure.conclusion}")
    except Skip as note:
        print(f"skipped: {note}")
    except MissingKey as error:
        sys.exit(f"{sys.argv[0]}: {error}")
