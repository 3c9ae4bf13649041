"""Parameter sweeps: one run per point, locally (Rust threads) or on Dask."""

from __future__ import annotations

import itertools
import math
from typing import Any, Dict, Iterator, List, Mapping, Optional, Sequence

from . import _pegdyn as _core
from ._pegdyn import SceneError
from ._scene import Limits, Scene, _limit_args, _list

#: Row fields every sweep row has, besides the inputs and the metrics.
FIXED = ("index", "outcome", "error", "stop", "t_end", "steps", "rhs_calls")


class SweepResult:
    """The rows of a sweep, one per point, in point order.

    Each row is a dict: ``index`` (point number), the input fields by
    their dotted keys, ``outcome`` (``"ok"``; ``"stopped"`` for an
    integration that stopped unplanned; ``"invalid"`` when the point's
    scene does not validate; ``"failed"`` when its run failed), ``error``
    (the message, or None), ``stop``, ``t_end``, ``steps``, ``rhs_calls``
    (None without a time integration) and every scalar result of the run
    summary, named ``"name [unit]"`` (``"name (summary)"`` where the name
    is one of those fields: the 3-D kinds' ``"outcome (summary)"`` is
    their outcome code, 0 for seated). When the scene has a
    ``[sensitivities]`` table, each row also has, per metric and field of
    its ``<name>.sensitivities.csv``, ``"d(metric)/d(field)"`` and
    ``"elasticity(metric, field)"`` (NaN where flagged) and, where flagged,
    ``"flag(metric, field)"`` with the reason: the derivatives at every
    point of the sweep.

    ``len(r)``, iteration over rows, ``r[i]`` (a row) and ``r["key"]`` (a
    column as a list) work; :meth:`to_pandas` gives a DataFrame.
    """

    def __init__(self, keys: Sequence[str], rows: List[Dict[str, Any]]):
        self.keys = list(keys)
        self.rows = rows

    def __len__(self) -> int:
        return len(self.rows)

    def __iter__(self) -> Iterator[Dict[str, Any]]:
        return iter(self.rows)

    def __getitem__(self, i):
        if isinstance(i, str):
            return [r.get(i) for r in self.rows]
        return self.rows[i]

    @property
    def columns(self) -> List[str]:
        """Column names: index, inputs, fixed fields, then metrics."""
        names: Dict[str, None] = dict.fromkeys(["index", *self.keys, *FIXED[1:]])
        for r in self.rows:
            names.update(dict.fromkeys(r))
        return list(names)

    def to_pandas(self):
        """The rows as a pandas DataFrame (requires pandas)."""
        import pandas as pd

        return pd.DataFrame(self.rows, columns=self.columns)

    def __repr__(self) -> str:
        return f"<pegdyn.SweepResult {len(self.rows)} rows over {self.keys}>"


def _plain(v: Any) -> Any:
    if hasattr(v, "tolist") and not isinstance(v, (str, bytes)):
        return v.tolist()
    return v


def _points(grid: Optional[Mapping[str, Sequence[Any]]], points) -> tuple:
    if (grid is None) == (points is None):
        raise ValueError("give either a grid {key: values} or points [{key: value}, ...]")
    if grid is not None:
        keys = list(grid)
        values = [[_plain(v) for v in grid[k]] for k in keys]
        return keys, [list(p) for p in itertools.product(*values)]
    pts = list(points)
    if not pts:
        return [], []
    keys = list(pts[0])
    out = []
    for i, p in enumerate(pts):
        if set(p) != set(keys):
            raise ValueError(f"point {i} has keys {sorted(p)}, point 0 has {sorted(keys)}")
        out.append([_plain(p[k]) for k in keys])
    return keys, out


def _check_keys(scene: Scene, keys: List[str], first: list) -> None:
    """Raises SceneError before any run when a swept key names no field of
    the scene (a typo such as ``pendulum.lenght``), listing the valid
    names; the first point's other problems (a value out of range) stay
    per-row outcomes."""
    for k in keys:
        if not isinstance(k, str) or not k or any(not part for part in k.split(".")):
            raise SceneError(f"pegdyn.sweep: `{k}` is not a dotted field name such as `pendulum.mass`")
    try:
        scene.with_values(dict(zip(keys, first)))
    except SceneError as e:
        unknown = [
            (field, reason)
            for field, _, reason in getattr(e, "errors", [])
            if field and reason.startswith("unknown field") and any(k == field or k.startswith(field + ".") for k in keys)
        ]
        if unknown:
            field, reason = unknown[0]
            key = next(k for k in keys if k == field or k.startswith(field + "."))
            err = SceneError(
                f"pegdyn.sweep: `{key}` names no field of this {scene.kind} scene (`{field}`: {reason});"
                " no point was run"
            )
            err.field, err.value, err.reason = field, None, reason
            err.errors = [(f, None, r) for f, r in unknown]
            raise err from None
    except ValueError as e:
        # A key whose table is a value (`pendulum.mass.x`).
        if "is not a table" in str(e):
            raise SceneError(f"pegdyn.sweep: {e}; no point was run") from None
        raise


def run_batch(
    text: str, name: str, keys: List[str], points: List[list], first: int, threads=None, limits=None
):
    """One Dask task: runs ``points`` (numbered from ``first``) in Rust and
    returns their rows. Module-level so that workers import it by name."""
    return _core.run_points(text, name, keys, points, first, threads, limits)


def _rows(keys, points, raw) -> List[Dict[str, Any]]:
    rows = []
    for r in raw:
        p = points[r["index"]]
        row = {"index": r["index"], **dict(zip(keys, p))}
        row.update((k, v) for k, v in r.items() if k != "index")
        rows.append(row)
    return rows


def sweep(
    scene: Scene,
    grid: Optional[Mapping[str, Sequence[Any]]] = None,
    points: Optional[Sequence[Mapping[str, Any]]] = None,
    client=None,
    batch_size: Optional[int] = None,
    threads: Optional[int] = None,
    limits: Limits = None,
) -> SweepResult:
    """Runs ``scene`` once per point and returns one row per run.

    ``grid``: ``{"table.field": values, ...}``, the Cartesian product in
    key order (the last key varies fastest); or ``points``: a list of
    ``{"table.field": value}`` dicts with the same keys. Each point's scene
    is the base scene with those fields replaced, validated like a scene
    file: a point that does not validate gives a row with outcome
    ``"invalid"`` rather than an exception. A key that names no field of
    the scene (a typo) raises :class:`SceneError` before any run, listing
    the table's valid names.

    Without ``client`` the points run in parallel on this machine (Rust
    threads, ``threads`` of them, default every core), with the GIL
    released; Ctrl-C interrupts.

    With a ``dask.distributed.Client``, the points are cut into batches of
    ``batch_size`` (default: about four batches per worker thread, so
    that a slow batch or a lost worker costs little), each batch one Dask
    task that runs its points in Rust on a worker, and the rows are
    gathered back in point order. A worker that dies mid-sweep makes the
    scheduler run its batches again elsewhere; every index is checked to
    come back exactly once. The rows are identical to the local sweep.
    Workers need this package (same version) installed; nothing else.

    The sweep is bounded before it starts, as one scene is: its points
    times the runs of one point (one, or the scene's grid) must stay within
    ``max_runs`` and their rows within ``max_memory_mb`` of the scene's
    ``[limits]``, with ``limits`` (default: the scene's own ``limits``)
    applied, e.g. ``limits={"max_runs": 100_000}``; else
    :class:`SceneError` names ``sweep`` and the limit. Each point's scene
    is validated under the same limits.
    """
    keys, pts = _points(grid, points)
    n = len(pts)
    args = _list(_limit_args(limits)) if limits is not None else _list(scene.limits)
    _core.check_sweep(scene.text, scene.name, n, args)
    if pts:
        _check_keys(scene, keys, pts[0])
    if client is None:
        raw = _core.run_points(scene.text, scene.name, keys, pts, 0, threads, args)
        return SweepResult(keys, _rows(keys, pts, raw))
    if batch_size is None:
        slots = max(1, sum(client.nthreads().values()))
        batch_size = max(1, math.ceil(n / (4 * slots)))
    if batch_size < 1:
        raise ValueError("batch_size must be at least 1")
    starts = list(range(0, n, batch_size))
    from dask.base import tokenize

    token = tokenize(scene.text, scene.name, keys, pts, batch_size, threads, args)
    futures = [
        client.submit(
            run_batch,
            scene.text,
            scene.name,
            keys,
            pts[s : s + batch_size],
            s,
            threads,
            args,
            key=f"pegdyn-sweep-{token}-{s}",
            retries=2,
        )
        for s in starts
    ]
    raw = [r for batch in client.gather(futures) for r in batch]
    raw.sort(key=lambda r: r["index"])
    if [r["index"] for r in raw] != list(range(n)):
        raise RuntimeError("pegdyn.sweep: rows lost or duplicated while gathering from Dask")
    return SweepResult(keys, _rows(keys, pts, raw))
