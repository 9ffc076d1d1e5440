"""The claims ledger: one row per checkable statement of the paper, declared, measured, judged.

A claim is *declared* (:class:`ClaimSpec`: id, where in the paper, the statement, the test, the
methods the evidence rests on, the verdict rule), then *measured* by its scene
(:class:`Measured`: the numbers, the cross-checks between independent methods, the evidence
text made from the numbers), then *judged* (:func:`judge`):

* if any cross-check failed -- two independent methods disagree beyond their stated accuracy --
  the verdict is "inconclusive", whatever the rule would say;
* otherwise the named rule turns the numbers into "holds", "holds approximately", "true but
  does not explain" (a sentence that is true but is offered as the explanation of a result it
  does not explain) or "fails".

A rule is best built by :func:`tiered_rule` from named :class:`Condition` objects: its text and
its logic then come from one definition (the same thresholds), so the rule a reader sees is the
rule that ran.

So a test can perturb the measured numbers (or a cross-check) and see the verdict change. A
verdict backed by methods of a single formulation (e.g. two solvers of Eq. ``inst1``) says so in
its evidence. A scene whose rows share a cross-check (the ring's two formulations) passes it once
to :func:`evaluate`; it is added to every row declared with ``shared_checks=True``.

Several scenes contribute rows; each calls :func:`update_ledger` with *its* rows, and rows from
other scenes already in ``claims.json`` are kept. ``claims.json`` is a list of objects with the
keys ``id``, ``section``, ``claim``, ``test``, ``evidence``, ``verdict`` (one of
:data:`VERDICTS`), ``scene``, ``figure``, ``numbers``, ``methods`` (list of {"name",
"formulation"}), ``rule``, ``cross_checks`` (list of {"name", "disagreement", "limit",
"passed"}), ``related`` (ids of rows that bear on this one), ``kind`` (one of :data:`KINDS`)
and ``root_cause`` (for a paper's statement that fails: a one-line statement of the independent
error of the paper it traces back to, a module-level constant shared by every row it explains,
else null). ``numbers`` may hold ``headline`` (the key numbers in a phrase) and ``finding`` (what
the row found, as a sentence made from its numbers: the report's headline lists these).
"""

from __future__ import annotations

import json
import math
from collections import Counter
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from reproduce.io import OutputFileError, json_value, read_json, write_text
from reproduce.tables import markdown_table

#: The verdict classes. "true but does not explain": the sentence is true, but it is offered as
#: the explanation of a result and does not explain it (the inference fails, not the fact).
VERDICTS = ("holds", "holds approximately", "true but does not explain", "fails",
            "inconclusive")
#: What a row is: a statement of the paper, a check of the package's own methods, or a modelling
#: caveat (a finding about what the paper leaves unspecified). The headline tallies the paper's
#: statements apart from the rest.
KINDS = ("paper", "package", "caveat")
#: The scenes in the order `python -m reproduce all` runs them; the ledger lists their rows in
#: the same order (rows of other scenes after them, alphabetically).
#: The sentence-by-sentence coverage of the paper (written by the claims scene).
COVERAGE_FILE = "coverage.md"
SCENE_ORDER = ("figure1", "claims", "ring", "convergence", "extremes", "dna")


@dataclass(frozen=True)
class Method:
    """A method behind a verdict and the formulation it starts from (e.g. "inst1", "energy",
    "Munder", "second variation", "closed form", "paper's figure")."""

    name: str
    formulation: str


@dataclass(frozen=True)
class CrossCheck:
    """Two independent determinations of one number: their disagreement against the accuracy
    they claim (``limit``). A non-finite disagreement fails."""

    name: str
    disagreement: float
    limit: float

    @property
    def passed(self) -> bool:
        return math.isfinite(self.disagreement) and self.disagreement <= self.limit


@dataclass(frozen=True)
class Rule:
    """A named verdict rule: ``text`` states it, ``decide`` applies it to the numbers."""

    text: str
    decide: Callable[[Mapping[str, Any]], str]


#: Comparison operators a :class:`Condition` may use, with the words its text uses.
_OPS: dict[str, tuple[Callable[[Any, Any], bool], str]] = {
    "<": (lambda a, b: a < b, "<"), "<=": (lambda a, b: a <= b, "≤"),
    ">": (lambda a, b: a > b, ">"), ">=": (lambda a, b: a >= b, "≥"),
    "true": (lambda a, _b: bool(a), ""), "false": (lambda a, _b: not a, ""),
}


@dataclass(frozen=True)
class Condition:
    """One named test of a rule: ``numbers[key] op threshold`` (``op`` "true"/"false" tests a
    boolean number and has no threshold). ``phrase`` names the number in the rule's text;
    ``fmt`` formats the threshold there (so the text shows the threshold the logic uses)."""

    key: str
    op: str
    phrase: str
    threshold: float | None = None
    fmt: str = "g"

    def __post_init__(self) -> None:
        if self.op not in _OPS:
            raise ValueError(f"op must be one of {sorted(_OPS)}, got {self.op!r}")
        if (self.threshold is None) != (self.op in ("true", "false")):
            raise ValueError(f"condition on {self.key!r}: a threshold goes with a comparison "
                             "operator and only with one")

    def met(self, numbers: Mapping[str, Any]) -> bool:
        """Whether `numbers` meet the condition (a missing or non-finite number does not)."""
        value = numbers.get(self.key)
        if value is None or (isinstance(value, float) and not math.isfinite(value)):
            return False
        return bool(_OPS[self.op][0](value, self.threshold))

    @property
    def text(self) -> str:
        if self.op == "true":
            return self.phrase
        if self.op == "false":
            return f"not {self.phrase}"
        return f"{self.phrase} {_OPS[self.op][1]} {self.threshold:{self.fmt}}"


def tiered_rule(tiers: Sequence[tuple[str, Sequence[Condition]]], otherwise: str,
                note: str = "") -> Rule:
    """A :class:`Rule` whose verdict is that of the first tier all of whose conditions are met
    (else `otherwise`), and whose text is made from the same conditions: "V1 if A and B; V2 if
    C; `otherwise` otherwise" (plus `note`, what the rule means, in parentheses)."""
    for verdict, _ in tiers:
        if verdict not in VERDICTS:
            raise ValueError(f"tier verdict {verdict!r} is not one of {VERDICTS}")
    if otherwise not in VERDICTS:
        raise ValueError(f"otherwise verdict {otherwise!r} is not one of {VERDICTS}")
    frozen = tuple((v, tuple(conds)) for v, conds in tiers)

    def decide(numbers: Mapping[str, Any]) -> str:
        return next((v for v, conds in frozen if all(c.met(numbers) for c in conds)), otherwise)

    text = "; ".join(f"{v} if " + " and ".join(c.text for c in conds) for v, conds in frozen)
    text += f"; {otherwise} otherwise" + (f" ({note})" if note else "")
    return Rule(text, decide)


@dataclass(frozen=True)
class ClaimSpec:
    """The declaration of a claim: what the paper says and how it is judged."""

    id: str
    section: str
    claim: str
    test: str
    methods: tuple[Method, ...]
    rule: Rule
    figure: str | None = None
    related: tuple[str, ...] = ()
    #: the scene's shared cross-checks bear on this row (it uses the numbers they check)
    shared_checks: bool = False
    #: why a single formulation is all there is (said in the evidence of such a verdict)
    one_formulation_why: str = "no independent formulation applies to it"
    #: one of :data:`KINDS`
    kind: str = "paper"
    #: for a row that fails: the independent error of the paper it traces back to (module
    #: docstring)
    root_cause: str | None = None

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"kind of {self.id} must be one of {KINDS}, got {self.kind!r}")


@dataclass(frozen=True)
class Measured:
    """What a scene measured for a claim: the rule's inputs, the evidence text, cross-checks."""

    numbers: dict[str, Any]
    evidence: str
    cross_checks: tuple[CrossCheck, ...] = ()


@dataclass(frozen=True)
class Claim:
    """A judged row of the ledger (what ``claims.json`` holds)."""

    id: str
    section: str
    claim: str
    test: str
    evidence: str
    verdict: str
    scene: str
    figure: str | None = None
    numbers: dict[str, Any] = field(default_factory=dict)
    methods: list[dict[str, str]] = field(default_factory=list)
    rule: str = ""
    cross_checks: list[dict[str, Any]] = field(default_factory=list)
    related: list[str] = field(default_factory=list)
    kind: str = "paper"
    root_cause: str | None = None

    def __post_init__(self) -> None:
        if self.verdict not in VERDICTS:
            raise ValueError(f"verdict must be one of {VERDICTS}, got {self.verdict!r}")


def formulations(methods: Sequence[Method]) -> list[str]:
    """The distinct starting points of `methods`, in order."""
    return list(dict.fromkeys(m.formulation for m in methods))


def judge(spec: ClaimSpec, measured: Measured, scene: str) -> Claim:
    """The verdict of `spec` on `measured` (module docstring) as a ledger row."""
    failed = [c for c in measured.cross_checks if not c.passed]
    verdict = "inconclusive" if failed else spec.rule.decide(measured.numbers)
    if verdict not in VERDICTS:
        raise ValueError(f"rule of {spec.id} returned {verdict!r}, not one of {VERDICTS}")
    evidence = measured.evidence
    if failed:
        evidence += (" INCONCLUSIVE: independent methods disagree beyond their stated accuracy: "
                     + "; ".join(f"{c.name} {c.disagreement:.1e} > {c.limit:.1e}"
                                 for c in failed) + ".")
    forms = formulations(spec.methods)
    if len(forms) < 2:
        evidence += (f" (This verdict rests on one formulation only: {forms[0] if forms else '-'};"
                     f" {spec.one_formulation_why}.)")
    return Claim(
        id=spec.id, section=spec.section, claim=spec.claim, test=spec.test, evidence=evidence,
        verdict=verdict, scene=scene, figure=spec.figure, numbers=measured.numbers,
        methods=[asdict(m) for m in spec.methods], rule=spec.rule.text,
        cross_checks=[{**asdict(c), "passed": c.passed} for c in measured.cross_checks],
        related=list(spec.related), kind=spec.kind, root_cause=spec.root_cause)


def with_shared(spec: ClaimSpec, measured: Measured, shared: Sequence[CrossCheck]) -> Measured:
    """`measured` with the scene's `shared` cross-checks first, if `spec` declares it uses them."""
    if not spec.shared_checks or not shared:
        return measured
    return Measured(measured.numbers, measured.evidence, (*shared, *measured.cross_checks))


def evaluate(claims: Sequence[tuple[ClaimSpec, Callable[[Any], Measured]]], evidence: Any,
             scene: str, claim_id: str | None = None,
             shared_checks: Sequence[CrossCheck] = ()) -> list[Claim]:
    """Judge every (declaration, measurement) pair of a scene on its evidence, or only the one
    `claim_id` (KeyError if the scene declares no such row); `shared_checks` join the
    cross-checks of the rows declared with ``shared_checks=True``."""
    rows = [judge(spec, with_shared(spec, measure(evidence), shared_checks), scene)
            for spec, measure in claims if claim_id is None or spec.id == claim_id]
    if claim_id is not None and not rows:
        raise KeyError(claim_id)
    return rows


#: Keys every ledger row has (what the report's headline relies on).
ROW_KEYS = ("id", "claim", "verdict")
#: Keys a row must have to be kept when a scene rewrites the ledger (its order, claims.md).
FULL_ROW_KEYS = (*ROW_KEYS, "scene", "section", "test", "evidence")


def read_ledger(path: Path, keys: tuple[str, ...] = ROW_KEYS) -> list[dict[str, Any]]:
    """Rows of an existing ``claims.json`` ([] if there is none); :class:`OutputFileError`
    naming the file if it is not a list of rows with `keys` and known verdicts."""
    if not path.exists():
        return []
    rows = read_json(path, list)
    if not all(isinstance(r, dict) and all(k in r for k in keys) for r in rows):
        raise OutputFileError(f"{path}: every row must be an object with the keys {keys}; "
                              "delete it to rebuild it")
    unknown = sorted({str(r["verdict"]) for r in rows} - set(VERDICTS))
    if unknown:
        raise OutputFileError(f"{path}: unknown verdicts {unknown} (allowed: {VERDICTS}); "
                              "delete it to rebuild it")
    return rows


def verdict_counts(verdicts: Iterable[str]) -> dict[str, int]:
    """How many of `verdicts` are each of :data:`VERDICTS` (in that order; zeros kept)."""
    counts = Counter(verdicts)
    return {v: counts[v] for v in VERDICTS}


def _methods_text(row: Mapping[str, Any]) -> str:
    return "; ".join(f"{m['name']} ({m['formulation']})" for m in row.get("methods", []))


def _markdown(rows: list[dict[str, Any]]) -> str:
    counts = verdict_counts(r["verdict"] for r in rows)
    lines = ["# Claims ledger", "",
             "Every checkable statement of Drozdov & Rabin, with the test, the methods it rests "
             "on (and their starting formulations), the computed evidence and a verdict by a "
             "stated rule (" + ", ".join(f"*{v}*" for v in VERDICTS[:-1])
             + f", or *{VERDICTS[-1]}* when independent methods disagree). Each row is a "
             "statement of the paper, a check of the package or a modelling caveat (its kind). "
             "Which sentence of the paper each row checks, and why the others have none: "
             f"`{COVERAGE_FILE}`. Generated by `python -m reproduce`; nothing here is typed in "
             "by hand.", "",
             ", ".join(f"{counts[v]} {v}" for v in VERDICTS) + f" ({len(rows)} rows).", "",
             markdown_table(["id", "where", "claim", "verdict"],
                            [[f"`{r['id']}`", r["section"], r["claim"], f"**{r['verdict']}**"]
                             for r in rows])]
    for r in rows:
        lines += ["", f"## `{r['id']}` — {r['verdict']}", "",
                  f"*Where:* {r['section']}  ", f"*Kind:* {r.get('kind', 'paper')}  ",
                  f"*Claim:* {r['claim']}  ",
                  f"*Test:* {r['test']}  ", f"*Methods:* {_methods_text(r)}  ",
                  f"*Rule:* {r.get('rule', '')}  ", f"*Evidence:* {r['evidence']}"]
        if r.get("root_cause"):
            lines.append(f"*Root cause:* {r['root_cause']}  ")
        if r.get("related"):
            lines.append(f"*Related:* {', '.join(f'`{x}`' for x in r['related'])}")
        if r.get("figure"):
            lines.append(f"\n![{r['id']}]({r['figure']})")
    return "\n".join(lines) + "\n"


def update_ledger(out_dir: Path, scene: str, claims: list[Claim]) -> list[Path]:
    """Replace the rows written by `scene` in ``claims.json``/``claims.md`` under `out_dir`."""
    json_path = Path(out_dir) / "claims.json"
    rows = [r for r in read_ledger(json_path, FULL_ROW_KEYS) if r["scene"] != scene]
    rows += [asdict(c) for c in claims]
    ids = [r["id"] for r in rows]
    dupes = sorted({i for i in ids if ids.count(i) > 1})
    if dupes:
        raise ValueError(f"duplicate claim ids in the ledger: {dupes}")
    order = {s: i for i, s in enumerate(SCENE_ORDER)}
    rows.sort(key=lambda r: (order.get(r["scene"], len(order)), r["scene"], r["id"]))
    write_text(json_path, json.dumps(rows, indent=2, default=json_value) + "\n")
    md_path = write_text(Path(out_dir) / "claims.md", _markdown(rows))
    return [json_path, md_path]


#: `python -m reproduce check` rules for the ledger rows a scene owns (rules in
#: reproduce/compare.py): evidence texts by their words and numbers, measured numbers to 1e-9
#: relative (1e-10 absolute for agreement measures at round-off), cross-check disagreements to
#: 1e-6 (they are round-off-level differences of two solvers), everything else exact (id, claim,
#: test, verdict, methods, rule, figure).
LEDGER_CHECK: dict[str, Any] = {
    "_owner": "scene", "*.evidence": "text", "*.numbers.headline": "text",
    "*.numbers.finding": "text",
    "*.numbers.*": {"rel": 1e-9, "abs": 1e-10},
    "*.cross_checks.*.disagreement": {"rel": 1e-6, "abs": 1e-10},
    "*": "exact"}


def ledger_check(numbers: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """:data:`LEDGER_CHECK` with a scene's own rules for some ``*.numbers.*`` keys, matched
    before the general ones (the first matching pattern applies) but after the prose keys
    (``headline``, ``finding``: compared as text whatever the scene's number rules say)."""
    prose = {k: v for k, v in LEDGER_CHECK.items() if v == "text"}
    return {**prose, **(numbers or {}), **LEDGER_CHECK}
