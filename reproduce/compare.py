"""Compare a regenerated output file with a committed one under declared tolerances.

Each scene declares, next to what it writes, a module-level ``CHECK`` mapping an output file
name (``.csv`` or ``.json``) to a *spec*: ``{pattern: rule}``, where `pattern` is a CSV column
name or a dotted JSON key path (``fnmatch`` wildcards; the first matching pattern wins) and
`rule` is one of

- ``"ignore"``: not compared (measured timings, anything machine-dependent);
- ``"exact"``: identical (verdicts, labels, booleans, integers; numbers compared as numbers);
- ``"text"``: prose with numbers in it: the words identical, each number within the rule's
  defaults or one and a half units of its last printed digit (rounding may flip that digit);
- a float ``r``: relative tolerance, ``|new - old| <= r |old|``;
- a dict with any of ``rel``, ``abs``, ``floor`` (the name of a column holding the solver's
  own relative error estimate for that row) and ``per_row`` (a pair (name, factor): an absolute
  slack of factor times the committed row's value of column, or sibling JSON key, `name`):
  ``|new - old| <= max(rel |old|, abs, max(est_old, est_new) |old|, factor row[name])``;
  and ``within``, for an achieved error whose digits depend on the engine and the BLAS (where
  an iteration stops, the order of its sums): a stated bound, a number or a pair (name,
  factor) giving factor times the committed row's `name` (its tol), which both the committed
  and the regenerated value must meet (``|old|, |new| <= bound``) for a change beyond the
  other terms to be allowed: the promise still holds, which is what such a number records.

- a :class:`Tie`: a label naming the lowest of competing values (the mode family), which may
  change only where those values tie (its ``tied`` callable, given the committed row, decides).

A spec may also hold ``"_owner": KEY`` (for a JSON list of rows with an ``id``, like
``claims.json``, which several scenes share): only the rows whose ``KEY`` equals the scene's
name are compared. Values no pattern matches are compared by :data:`DEFAULT_RULE` and reported
as undeclared. Non-finite numbers must match exactly; a missing file, column, row or key, or a
changed number of rows, is a regression. CSV cells are parsed one by one (a number where the
text is one, else the text; an empty cell is ``"(missing)"``), so a garbled or missing committed
cell is one regression showing that cell, and leaves the rest of its column compared as numbers.

>>> rule_allows({"rel": 1e-9}, 1.0, 1.0 + 1e-10)
True
>>> rule_allows({"rel": 1e-9}, 1.0, 1.0 + 1e-6)
False
"""

from __future__ import annotations

import csv
import fnmatch
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from reproduce.io import read_json

#: Rule for values that no pattern of the scene's CHECK matches.
DEFAULT_RULE: dict[str, float] = {"rel": 1e-9}
#: Absolute slack for numbers inside prose (``"text"``): values this small printed in the
#: evidence are round-off or solver-agreement measures (e.g. ``4.2e-16``, ``2.2e-11 in Omega``),
#: noise rather than results.
TEXT_ABS = 1e-10
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
#: A CSV cell that is a number as pandas writes one (``nan`` and ``inf`` included).
_CSV_NUMBER = re.compile(r"^[-+]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf)$",
                         re.IGNORECASE)
#: How an empty CSV cell or an absent JSON key is shown.
MISSING = "(missing)"


@dataclass(frozen=True)
class Tie:
    """Rule for a label that names the lowest of competing values (e.g. the mode family of
    p*): where those values tie, which one is named is not a result, so a changed label is
    allowed exactly where ``tied(row)`` (the committed row, column -> value) is true.
    `meaning` states the tie in words for the report."""

    tied: Callable[[Mapping[str, Any]], bool]
    meaning: str


@dataclass
class Difference:
    """One compared value that changed: where, the two values, and whether it is allowed."""

    file: str
    where: str
    committed: Any
    regenerated: Any
    allowed: str
    regression: bool


@dataclass
class FileComparison:
    """Outcome for one file: how many values were compared, which changed, which undeclared."""

    file: str
    compared: int = 0
    ignored: int = 0
    differences: list[Difference] = field(default_factory=list)
    undeclared: set[str] = field(default_factory=set)

    @property
    def regressions(self) -> list[Difference]:
        return [d for d in self.differences if d.regression]


def _is_number(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def _both_nan(a: Any, b: Any) -> bool:
    return _is_number(a) and _is_number(b) and math.isnan(a) and math.isnan(b)


def _as_rule(rule: Any) -> Any:
    return {"rel": float(rule)} if _is_number(rule) else rule


def rule_for(spec: dict[str, Any], name: str) -> tuple[Any, bool]:
    """The rule of the first pattern in `spec` matching `name`, and whether one was declared."""
    for pattern, rule in spec.items():
        if not pattern.startswith("_") and fnmatch.fnmatchcase(name, pattern):
            return _as_rule(rule), True
    return DEFAULT_RULE, False


def _last_digit_unit(token: str) -> float:
    """Value of one unit in the last printed digit of a number token ('8.27e-04' -> 1e-6)."""
    mantissa, _, exponent = token.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 10.0 ** (int(exponent or 0) - decimals)


def _text_allows(old: str, new: str) -> bool:
    if _NUMBER.sub("#", old) != _NUMBER.sub("#", new):
        return False
    for a, b in zip(_NUMBER.findall(old), _NUMBER.findall(new), strict=True):
        slack = max(TEXT_ABS, DEFAULT_RULE["rel"] * abs(float(a)),
                    1.5 * max(_last_digit_unit(a), _last_digit_unit(b)))
        if abs(float(a) - float(b)) > slack:
            return False
    return True


def rule_allows(rule: Any, old: Any, new: Any, est: tuple[float, float] = (0.0, 0.0),
                row_slack: float = 0.0, bound: float = math.nan) -> bool:
    """Whether `new` may replace `old` under `rule` (`est`: the row's error estimates;
    `row_slack`: its ``per_row`` slack; `bound`: its ``within`` bound, NaN for none).

    >>> rule_allows({"rel": 1e-3, "per_row": ("tol", 0.01)}, 8.1e-11, 8.2e-11, row_slack=1e-8)
    True
    >>> rule_allows({"rel": 1e-5, "within": 1e-4}, 2.4e-10, 4.5e-9, bound=1e-4)
    True
    >>> rule_allows({"rel": 1e-5, "within": 1e-4}, 2.4e-10, 2e-4, bound=1e-4)
    False
    """
    if rule == "ignore":
        return True
    if rule == "text" and isinstance(old, str) and isinstance(new, str):
        return _text_allows(old, new)
    if not (_is_number(old) and _is_number(new)):
        return old == new
    if not (math.isfinite(old) and math.isfinite(new)):
        return old == new or (math.isnan(old) and math.isnan(new))
    if rule in ("exact", "text"):
        return old == new
    scale = max(rule.get("rel", 0.0), *(e for e in est if math.isfinite(e))) * abs(old)
    if abs(old) <= bound and abs(new) <= bound:  # False for a NaN bound
        return True
    return abs(new - old) <= max(scale, rule.get("abs", 0.0), row_slack)


def _bound(rule: Any, row: Mapping[str, Any]) -> float:
    """The ``within`` bound of `rule` for the committed `row` (NaN where there is none)."""
    within = rule.get("within") if isinstance(rule, dict) else None
    if within is None:
        return math.nan
    if _is_number(within):
        return float(within)
    return within[1] * _number(row.get(within[0]))


def _describe(rule: Any) -> str:
    if isinstance(rule, Tie):
        return f"tie ({rule.meaning})"
    if isinstance(rule, dict):
        return ", ".join(f"{k} {v:g}" if _is_number(v) else f"{k} {v}" for k, v in rule.items())
    return str(rule)


def _cell(text: str) -> Any:
    """A CSV cell as a Python value: a float where the text is a number (exactly as Python
    reads it), :data:`MISSING` where it is empty, else the text."""
    if _CSV_NUMBER.match(text):
        return float(text)
    return text if text else MISSING


def _read_csv(path: Path) -> tuple[list[str], list[list[Any]]]:
    """Header and rows of a CSV file, every cell by :func:`_cell` (short rows padded with
    :data:`MISSING`)."""
    with path.open(newline="", encoding="utf-8") as f:
        lines = list(csv.reader(f))
    header = lines[0] if lines else []
    rows = [[_cell(c) for c in line] + [MISSING] * (len(header) - len(line))
            for line in lines[1:] if line]
    return header, rows


def _number(x: Any) -> float:
    """A cell used as a number by another column's rule (an estimate, a slack): NaN if it is
    not one (a garbled estimate then gives no slack, and its own cell is reported)."""
    return float(x) if _is_number(x) else math.nan


def compare_csv(name: str, old_path: Path, new_path: Path, spec: dict[str, Any]
                ) -> FileComparison:
    """Compare two CSV files row by row, column by column, under `spec`."""
    out = FileComparison(name)
    (cols, old), (new_cols, new) = _read_csv(old_path), _read_csv(new_path)
    if cols != new_cols or len(old) != len(new):
        out.differences.append(Difference(
            name, "shape", f"{len(old)} rows x {cols}", f"{len(new)} rows x {new_cols}",
            "same rows and columns", True))
        return out
    index = {c: j for j, c in enumerate(cols)}
    for j, col in enumerate(cols):
        rule, declared = rule_for(spec, col)
        if not declared:
            out.undeclared.add(col)
        if rule == "ignore":
            out.ignored += len(old)
            continue
        floor = rule.get("floor") if isinstance(rule, dict) else None
        per_row = rule.get("per_row") if isinstance(rule, dict) else None
        for i, (old_row, new_row) in enumerate(zip(old, new, strict=True)):
            a, b = old_row[j], new_row[j]
            out.compared += 1
            if a == b or _both_nan(a, b):
                continue
            if isinstance(rule, Tie):
                allowed = rule.tied(dict(zip(cols, old_row, strict=True)))
            else:
                est = ((_number(old_row[index[floor]]), _number(new_row[index[floor]]))
                       if floor in index else (0.0, 0.0))
                slack = (per_row[1] * _number(old_row[index[per_row[0]]])
                         if per_row and per_row[0] in index else 0.0)
                allowed = rule_allows(rule, a, b, est, 0.0 if math.isnan(slack) else slack,
                                      _bound(rule, dict(zip(cols, old_row, strict=True))))
            out.differences.append(Difference(name, f"row {i + 2}, {col}", a, b,
                                              _describe(rule), not allowed))
    return out


def _flatten(obj: Any, prefix: str = "") -> dict[str, Any]:
    """Leaves of a JSON value by dotted path; rows of a list with ``id`` keys go by that id."""
    if isinstance(obj, dict):
        items = [(str(k), v) for k, v in obj.items()]
    elif isinstance(obj, list):
        keyed = all(isinstance(r, dict) and "id" in r for r in obj) and obj
        items = [(str(r["id"]) if keyed else str(i), r) for i, r in enumerate(obj)]
    else:
        return {prefix: obj}
    flat: dict[str, Any] = {}
    for key, value in items:
        flat.update(_flatten(value, f"{prefix}.{key}" if prefix else key))
    return flat or {prefix: obj}


def _owned(rows: Any, owner: str | None, scene: str) -> Any:
    if owner is None or not isinstance(rows, list):
        return rows
    return [r for r in rows if isinstance(r, dict) and r.get(owner) == scene]


def compare_json(name: str, old_path: Path, new_path: Path, spec: dict[str, Any],
                 scene: str) -> FileComparison:
    """Compare two JSON files leaf by leaf under `spec`."""
    out = FileComparison(name)
    owner = spec.get("_owner")
    old = _flatten(_owned(read_json(old_path, object), owner, scene))
    new = _flatten(_owned(read_json(new_path, object), owner, scene))
    for key in sorted(set(old) | set(new)):
        rule, declared = rule_for(spec, key)
        if not declared:
            out.undeclared.add(key)
        if rule == "ignore":
            out.ignored += 1
            continue
        out.compared += 1
        if key not in old or key not in new:
            out.differences.append(Difference(name, key, old.get(key, MISSING),
                                              new.get(key, MISSING), "present", True))
        elif old[key] != new[key] and not _both_nan(old[key], new[key]):
            allowed = (rule.tied(_siblings(key, old)) if isinstance(rule, Tie) else
                       rule_allows(rule, old[key], new[key],
                                   row_slack=_json_slack(rule, key, old),
                                   bound=_bound(rule, _siblings(key, old))))
            out.differences.append(Difference(name, key, old[key], new[key], _describe(rule),
                                              not allowed))
    return out


def _siblings(key: str, flat: dict[str, Any]) -> dict[str, Any]:
    """The JSON object holding `key`, as last key -> value (a :class:`Tie`'s row)."""
    parent = key.rpartition(".")[0]
    return {k.rpartition(".")[2]: v for k, v in flat.items() if k.rpartition(".")[0] == parent}


def _json_slack(rule: Any, key: str, flat: dict[str, Any]) -> float:
    """The ``per_row`` slack of `key` from its sibling key in the committed JSON (0 if none)."""
    per_row = rule.get("per_row") if isinstance(rule, dict) else None
    if not per_row:
        return 0.0
    sibling = flat.get(f"{key.rpartition('.')[0]}.{per_row[0]}")
    return per_row[1] * float(sibling) if _is_number(sibling) else 0.0


def compare_file(name: str, committed_dir: Path, fresh_dir: Path, spec: dict[str, Any] | str,
                 scene: str) -> FileComparison:
    """Compare ``committed_dir/name`` with ``fresh_dir/name`` (CSV or JSON) under `spec`."""
    old_path, new_path = committed_dir / name, fresh_dir / name
    if spec == "ignore":
        return FileComparison(name)
    spec = spec if isinstance(spec, dict) else {}
    if not (old_path.exists() and new_path.exists()):
        state = {True: "present", False: "(missing)"}
        return FileComparison(name, differences=[Difference(
            name, "file", state[old_path.exists()], state[new_path.exists()], "present", True)])
    if name.endswith(".csv"):
        return compare_csv(name, old_path, new_path, spec)
    return compare_json(name, old_path, new_path, spec, scene)
