"""Scenes: load, validate, run; the result of a run as numpy arrays."""

from __future__ import annotations

import os
import html
from dataclasses import dataclass, field
from typing import Any, Dict, List, Mapping, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from . import _pegdyn as _core

PathLike = Union[str, "os.PathLike[str]"]

#: Work limits: ``{"max_runs": 10_000}`` or ``["max_runs=1e4"]``, the keys of
#: a scene's ``[limits]`` table (the ``max_`` prefix may be left out), as
#: ``pegdyn run --limit KEY=VALUE``.
Limits = Union[Mapping[str, Union[int, float, str]], Sequence[str], None]


def _limit_args(limits: Limits) -> Optional[Tuple[str, ...]]:
    """``limits`` as ``KEY=VALUE`` strings (None for none); checked by the
    core, which raises ValueError naming an unusable one."""
    if limits is None:
        return None
    if isinstance(limits, str):
        raise TypeError('limits: give a dict {"max_runs": 10000} or a list of "KEY=VALUE" strings')
    if isinstance(limits, Mapping):
        out = []
        for k, v in limits.items():
            if isinstance(v, float) and v.is_integer() and abs(v) < 2.0**64:
                v = int(v)
            out.append(f"{k}={v}")
        return tuple(out)
    return tuple(str(a) for a in limits)


def kinds() -> List[Tuple[str, str]]:
    """Every scene kind pegdyn knows, as ``(kind, description)`` pairs."""
    return list(_core.kinds())


class Scene:
    """A validated scene: TOML text plus the name its outputs are given.

    Build one with :func:`load`, :func:`loads` or :func:`from_dict`; the
    constructor validates (raises :class:`SceneError`), under the scene's
    ``[limits]`` with ``limits`` applied (as ``pegdyn check --limit``): a
    scene asking for more work than the limits allow is refused before
    anything is built. A scene is immutable and cheap to pickle (it is its
    text, name and limits), so it travels to Dask workers as is.

    Attributes: ``text`` (TOML), ``name`` (stem of output files; it cannot
    contain ``.``), ``kind``, ``description`` (or None), ``limits`` (the
    ``KEY=VALUE`` overrides, or None).
    """

    __slots__ = ("text", "name", "kind", "description", "limits", "_describe")

    def __init__(
        self,
        text: str,
        name: str = "scene",
        *,
        limits: Limits = None,
        _prefix: Optional[str] = None,
    ):
        args = _limit_args(limits)
        kind, description, describe = _core.check(text, name, _prefix, _list(args))
        self.text = text
        self.name = name
        self.limits = args
        self.kind = kind
        self.description = description
        self._describe = describe

    def describe(self) -> str:
        """One line saying what the scene simulates (as ``pegdyn check`` prints)."""
        return self._describe

    def with_values(self, values: Mapping[str, Any]) -> "Scene":
        """A copy with dotted fields replaced, e.g. ``{"pendulum.mass": 2.0}``
        (validated: raises :class:`SceneError`)."""
        keys = list(values)
        text = _core.set_fields(self.text, keys, [values[k] for k in keys])
        return Scene(text, self.name, limits=self.limits)

    def run(self, out: Optional[PathLike] = None) -> "Result":
        """Runs the scene and returns a :class:`Result`.

        ``out``: a directory to write ``<name>.csv``, ``<name>.svg`` (and
        the scene's other files, ``<name>.<part>.<ext>``) into, with the
        run manifest ``<name>.run.toml``, as ``pegdyn run --out`` does; the
        paths are in ``Result.paths`` (the manifest is not among them). Without it nothing is written: the
        tables are kept in memory (the same numbers the files would hold,
        bit for bit) and figures are not drawn (only checked, so a run
        fails the same way as with files).

        The run releases the GIL; Ctrl-C (KeyboardInterrupt) returns at
        once (the abandoned integration finishes in a background thread
        and its output is discarded). Raises :class:`RunError` if the run
        fails; an integration that stops unplanned is *not* an exception:
        see ``Result.outcome.success``.
        """
        limits = _list(self.limits)
        if out is None:
            return _result(_core.run(self.text, self.name, None, limits), self.name, self.kind)
        os.makedirs(out, exist_ok=True)
        return _result(_core.run(self.text, self.name, os.fspath(out), limits), self.name, self.kind)

    def __reduce__(self):
        return (_restore, (self.text, self.name, self.limits))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scene) and (self.text, self.name, self.limits) == (
            other.text,
            other.name,
            other.limits,
        )

    def __hash__(self) -> int:
        return hash((self.text, self.name, self.limits))

    def __repr__(self) -> str:
        return f"<pegdyn.Scene {self.name!r} kind={self.kind!r}: {self._describe}>"


def _list(args: Optional[Tuple[str, ...]]) -> Optional[List[str]]:
    return None if args is None else list(args)


def _restore(text: str, name: str, limits: Optional[Tuple[str, ...]]) -> Scene:
    return Scene(text, name, limits=limits)


def load(path: PathLike, *, limits: Limits = None) -> Scene:
    """Reads and validates the scene file at ``path``; the scene is named
    after the file stem (as ``pegdyn run`` names its outputs). Errors carry
    ``pegdyn check``'s message, prefixed with the path the same way.
    ``limits`` as for :class:`Scene`."""
    p = os.fspath(path)
    with open(p, encoding="utf-8") as fh:
        text = fh.read()
    name = os.path.splitext(os.path.basename(p))[0] or "scene"
    return Scene(text, name, limits=limits, _prefix=p)


def loads(text: str, name: str = "scene", *, limits: Limits = None) -> Scene:
    """Validates scene TOML ``text``; outputs are named after ``name``.
    ``limits`` as for :class:`Scene`."""
    return Scene(text, name, limits=limits)


def from_dict(d: Mapping[str, Any], name: str = "scene", *, limits: Limits = None) -> Scene:
    """Validates a scene given as a dict (nested dicts are TOML tables,
    values bool/int/float/str/lists; numpy scalars and arrays accepted).
    ``limits`` as for :class:`Scene`."""
    return Scene(_core.to_toml(dict(d)), name, limits=limits)


class Event(NamedTuple):
    """An event that fired during an integration, as ``(t, name, details)``.

    - ``t``: located time (s);
    - ``name``: the scene's name for it (``#index`` when unnamed);
    - ``details``: ``terminal`` (True when it ended the integration) and
      named numbers: for an integrator event ``direction`` (+1 rising
      through zero, -1 falling) and the state there, ``x[0]``, ``x[1]``,
      ... in the scene's state order; for the rigid peg's restarts from
      rest ``direction_gamma`` and ``direction_psi``.
    """

    t: float
    name: str
    details: Dict[str, Any]

    @property
    def terminal(self) -> bool:
        """Whether this event ended the integration."""
        return bool(self.details.get("terminal", False))


@dataclass(frozen=True)
class Outcome:
    """How a run ended. ``success`` is False when the integration stopped
    unplanned (``pegdyn run`` exits 1 then). The other fields are None for
    scenes without a time integration (e.g. the jamming tables)."""

    success: bool
    stop: Optional[str] = None
    t_end: Optional[float] = None
    method: Optional[str] = None
    steps: Optional[int] = None
    rejected: Optional[int] = None
    rhs_calls: Optional[int] = None


@dataclass
class Result:
    """What a run produced.

    - ``columns``: the main table ``<name>.csv`` as a dict of numpy float64
      arrays (text columns as lists of str), exactly the numbers written;
    - ``tables``: every CSV the run wrote, by file stem;
    - ``outcome``: an :class:`Outcome`; ``events``: every :class:`Event`
      that fired, in time order (a terminal one last);
    - ``metrics``: scalar results ``{name: value}``; ``units`` their units;
    - ``notes``: results in words ``{name: text}``: a coded metric's
      meaning (``outcome``: ``"seated"``) and notes without a value (a
      sweep's ``diagram check`` that was not made, and why);
    - ``summary``: the raw summary dict; ``text``: what ``pegdyn run`` prints;
    - ``paths``: files written (empty when ``run`` had no ``out``);
    - ``kind``: the scene's kind.

    The run's replay page (``docs/replay.md``; the 3-D kinds and
    ``insert_compliant``, unless the scene says ``[replay] page = false``)
    shows inline in a Jupyter notebook (:meth:`_repr_html_`) and
    :meth:`replay` writes it to a file. A run in memory keeps the page; a
    run into a directory reads it from its file there.
    """

    columns: Dict[str, Any]
    tables: Dict[str, Dict[str, Any]]
    outcome: Outcome
    events: List[Event]
    metrics: Dict[str, float]
    units: Dict[str, str]
    summary: Dict[str, Any]
    text: str
    paths: List[str]
    kind: Optional[str] = None
    notes: Dict[str, str] = field(default_factory=dict)
    _page: Optional[bytes] = field(default=None, repr=False, compare=False)

    def _page_bytes(self) -> Optional[bytes]:
        if self._page is not None:
            return self._page
        for p in self.paths:
            if p.endswith(".html"):
                with open(p, "rb") as fh:
                    return fh.read()
        return None

    @property
    def has_replay(self) -> bool:
        """Whether the run made a replay page."""
        return self._page is not None or any(p.endswith(".html") for p in self.paths)

    def replay(self, path: PathLike) -> str:
        """Writes the run's replay page (one self-contained HTML file that
        opens from disk with no network) to ``path``; returns the path.

        Raises ValueError when the run has no page: its kind makes none
        (the pendulums, the rigid peg, jamming), or the scene turned it off
        with ``[replay] page = false``. A sweep's runs make no page: run the
        point's scene (``scene.with_values(point).run()``) to see one.
        """
        page = self._page_bytes()
        if page is None:
            raise ValueError(
                f"this {self.kind or 'scene'} run has no replay page: pages are made by the "
                "compliant 3-D peg kinds (drop_3d, insert_rcc, rotation_assist, design_margins) "
                "and insert_compliant, unless the scene says [replay] page = false"
            )
        out = os.fspath(path)
        with open(out, "wb") as fh:
            fh.write(page)
        return out

    def _repr_html_(self) -> Optional[str]:
        """The replay page inline (Jupyter): an iframe whose ``srcdoc`` is
        the page, sandboxed to run its scripts only; None without a page
        (Jupyter then shows the plain repr)."""
        page = self._page_bytes()
        if page is None:
            return None
        doc = html.escape(page.decode("utf-8"), quote=True)
        return (
            '<iframe sandbox="allow-scripts" style="width:100%;height:760px;border:0" '
            f'title="pegdyn replay" srcdoc="{doc}"></iframe>'
        )

    @property
    def sensitivities(self) -> Optional[Dict[str, Any]]:
        """The derivatives a ``[sensitivities]`` table asked for
        (``<name>.sensitivities.csv``, ``docs/sensitivities.md``) as numpy
        arrays, one entry per (metric, field) row: ``metric`` and
        ``parameter`` (str), ``value`` (the metric's value), ``derivative``,
        ``elasticity`` (float64; NaN where the file's cell is empty: a
        flagged derivative, a metric without a value) and ``flag`` (str:
        why there is no derivative, or ``"not used by this model"``; empty
        where the derivative holds). A grid's table (``rotation_assist``)
        adds each row's grid point, its coordinate columns as float64
        arrays (``lateral_error_m``, ``angular_error_deg``,
        ``precession_rate``, ``spin_rate``). None when the scene has no such
        table.
        """
        table = next((t for k, t in self.tables.items() if k.endswith(".sensitivities")), None)
        if table is None:
            return None

        def numbers(column: Any) -> Any:
            if isinstance(column, list):
                return np.array([float(c) if c != "" else np.nan for c in column], dtype=np.float64)
            return np.asarray(column, dtype=np.float64)

        def text(column: Any) -> Any:
            return np.array([str(c) for c in column], dtype=str)

        out = {
            "metric": text(table["metric"]),
            "parameter": text(table["parameter"]),
            "value": numbers(table["value"]),
            "derivative": numbers(table["derivative"]),
            "elasticity": numbers(table["elasticity"]),
            "flag": text(table["flag"]),
        }
        for key, column in table.items():
            if key not in out:
                out[key] = numbers(column)
        return out

    def to_pandas(self, table: Optional[str] = None):
        """The main table (or ``tables[table]``) as a pandas DataFrame
        (requires pandas)."""
        import pandas as pd

        return pd.DataFrame(self.columns if table is None else self.tables[table])


def _result(summary: Dict[str, Any], name: str, kind: Optional[str] = None) -> Result:
    files = summary.pop("files", None) or {}
    outputs = list(summary["outputs"])
    tables: Dict[str, Dict[str, Any]] = summary["tables"] or {}
    if summary["tables"] is None:
        for p in outputs:
            if p.endswith(".csv"):
                tables[os.path.splitext(os.path.basename(p))[0]] = _core.read_csv(p)
    # The main table is `<name>.csv` when the scene writes one, else the first.
    main = tables.get(name, next(iter(tables.values()), {}))
    integ = summary["integration"]
    events = [Event(t, n, dict(d)) for t, n, d in summary["events"]]
    if integ is None:
        outcome = Outcome(success=bool(summary["success"]))
    else:
        outcome = Outcome(
            success=integ["success"],
            stop=integ["stop"],
            t_end=integ["t_end"],
            method=integ["method"],
            steps=integ["steps"],
            rejected=integ["rejected"],
            rhs_calls=integ["rhs_calls"],
        )
    return Result(
        columns=main,
        tables=tables,
        outcome=outcome,
        events=events,
        # A note has text and no value: it goes to ``notes``, not ``metrics``.
        metrics={n: v for n, v, _, t in summary["metrics"] if t is None or v == v},
        units={n: u for n, v, u, t in summary["metrics"] if t is None or v == v},
        summary=summary,
        text=summary["text"],
        paths=outputs,
        kind=kind,
        notes={n: t for n, _, _, t in summary["metrics"] if t is not None},
        _page=next((b for f, b in files.items() if f.endswith(".html")), None),
    )
