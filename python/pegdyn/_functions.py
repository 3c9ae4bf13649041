"""The generated model functions, evaluated on numpy arrays in a Rust loop."""

from __future__ import annotations

import warnings
from types import SimpleNamespace
from typing import Dict, List, Optional, Tuple

import numpy as np

from . import _pegdyn as _core

#: The ``errors=`` choices of a :class:`Function` call.
ERRORS = ("warn", "raise", "propagate")


class NonFiniteWarning(RuntimeWarning):
    """A generated function met a NaN or infinite input, or gave a NaN or
    infinite output from finite inputs (``errors="warn"``, the default).
    Filter it like any warning, e.g.
    ``warnings.simplefilter("ignore", pegdyn.NonFiniteWarning)``."""


def _first_bad(a: np.ndarray, rows: Optional[np.ndarray]) -> Optional[Tuple[int, int, int]]:
    """(row, column, count) of the first non-finite entry of the 2-D array
    `a` among `rows` (a boolean row selection, None for all)."""
    if np.isfinite(a.sum()):
        # A NaN or an infinity reaches the sum: a finite sum has none (one
        # fast pass; an overflowing sum falls through to the exact count).
        return None
    bad = ~np.isfinite(a)
    if rows is not None:
        bad &= rows[:, None]
    count = int(bad.sum())
    if count == 0:
        return None
    r, c = np.argwhere(bad)[0]
    return int(r), int(c), count


def _entry(a: np.ndarray, r: int, c: int) -> str:
    v = a[r, c]
    return "NaN" if np.isnan(v) else ("inf" if v > 0 else "-inf")


class Function:
    """One generated function (``pegdyn codegen`` / ``docs/generated/``),
    vectorized over points.

    Call it with one array per input, in the order of ``inputs``:

    - a 2-D array of shape ``(N, len)`` gives N points (one row each);
      shape ``(1, len)`` is broadcast to every point (shared parameters);
    - a 1-D array of shape ``(len,)`` is one point (a row shared by all).

    Arrays must be real numbers (float64; integer arrays and Python
    lists are converted); anything else raises TypeError, and a wrong
    column count or disagreeing row counts raise ValueError.

    Returns a dict ``{output name: array}``: shape ``(N,)`` for a scalar
    output, ``(N, k)`` for a vector or matrix (row-major, k entries). When
    every input is 1-D the leading axis is dropped (floats and ``(k,)``
    arrays). :meth:`raw` returns the flat ``(N, total)`` array instead.

    Non-finite values, as numpy's floating-point error handling treats
    them (``errors=`` keyword):

    - ``"warn"`` (default): a NaN or infinite input, or a NaN or infinite
      output from finite inputs (a point outside the model's domain),
      issues one :class:`NonFiniteWarning` naming the input or output
      component, the first row and how many entries; the values are
      returned as computed (a NaN input gives NaN outputs);
    - ``"raise"``: the same cases raise ValueError with that message,
      before anything is returned;
    - ``"propagate"``: no check, no warning (numpy's ufuncs on NaN).

    Masked arrays (``numpy.ma``) are honoured, not unmasked: a point
    (row) with any masked input component gives masked outputs (a
    ``numpy.ma.MaskedArray``; ``numpy.ma.masked`` for a single point), and
    masked entries are never reported as non-finite.

    Attributes: ``module``, ``name``, ``inputs`` (list of ``(argument,
    [symbol, ...])``), ``outputs`` (list of ``(name, entries)``).
    """

    def __init__(self, module: str, name: str, inputs, outputs):
        self.module = module
        self.name = name
        self.inputs: List[Tuple[str, List[str]]] = [(a, list(s)) for a, s in inputs]
        self.outputs: List[Tuple[str, int]] = [(n, int(k)) for n, k in outputs]
        args = ", ".join(f"{a}[N, {len(s)}]" for a, s in self.inputs)
        rets = ", ".join(f"{n}: [N]" if k == 1 else f"{n}: [N, {k}]" for n, k in self.outputs)
        syms = "\n".join(f"    {a}: {', '.join(s)}" for a, s in self.inputs)
        self.__doc__ = (
            f"{module}::{name}({args}) -> {{{rets}}}\n\nInput components:\n{syms}\n\n"
            + (Function.__doc__ or "")
        )

    @property
    def path(self) -> str:
        """``module::name``."""
        return f"{self.module}::{self.name}"

    def _arrays(self, args) -> Tuple[List[np.ndarray], bool, Optional[List[np.ndarray]]]:
        """The inputs as C-contiguous float64 2-D arrays, whether every
        input was 1-D, and each input's row mask (None without a masked
        array among them)."""
        if len(args) != len(self.inputs):
            names = ", ".join(a for a, _ in self.inputs)
            raise TypeError(f"{self.path}: takes {len(self.inputs)} inputs ({names}), got {len(args)}")
        out = []
        masks: List[np.ndarray] = []
        masked = False
        single = True
        for (arg, syms), x in zip(self.inputs, args):
            if np.ma.isMaskedArray(x):
                masked = True
                mask = np.ma.getmaskarray(x)
                a = np.ma.getdata(x)
            else:
                a = np.asarray(x)
                mask = None
            if a.dtype.kind not in "fiu" or a.dtype.itemsize > 8 and a.dtype.kind == "f":
                raise TypeError(f"{self.path}: input `{arg}` must be real numbers (float64), got dtype {a.dtype}")
            if a.ndim == 1:
                a = a.reshape(1, -1)
            elif a.ndim == 2:
                single = False
            else:
                raise ValueError(
                    f"{self.path}: input `{arg}` must have shape (N, {len(syms)}) or ({len(syms)},), got {a.shape}"
                )
            masks.append(np.zeros(a.shape[0], dtype=bool) if mask is None else mask.reshape(a.shape).any(axis=1))
            out.append(np.ascontiguousarray(a, dtype=np.float64))
        return out, single, (masks if masked else None)

    def _evaluate(self, args, errors: str) -> Tuple[np.ndarray, bool, Optional[np.ndarray]]:
        """The flat outputs, whether every input was 1-D, and the row mask
        of the outputs (None without masked inputs); checks non-finite
        values as `errors` says."""
        if errors not in ERRORS:
            raise ValueError(f"{self.path}: errors must be one of {', '.join(map(repr, ERRORS))}, got {errors!r}")
        arrays, single, masks = self._arrays(args)
        flat = _core.evaluate(self.module, self.name, arrays)
        row_mask = None
        if masks is not None:
            row_mask = np.zeros(flat.shape[0], dtype=bool)
            for m in masks:
                row_mask |= m if m.shape[0] == flat.shape[0] else m[:1].repeat(flat.shape[0])
        if errors != "propagate":
            self._check(arrays, masks, flat, row_mask, errors)
        return flat, single, row_mask

    def _check(self, arrays, masks, flat, row_mask, errors: str) -> None:
        keep = None if row_mask is None else ~row_mask
        message = None
        for j, ((arg, syms), a) in enumerate(zip(self.inputs, arrays)):
            own = None if masks is None else ~masks[j]
            hit = _first_bad(a, own)
            if hit is not None:
                r, c, count = hit
                if message is None:
                    where = "" if a.shape[0] == 1 and flat.shape[0] != 1 else f" at row {r}"
                    message = (
                        f"{self.path}: input `{arg}` component `{syms[c]}` is {_entry(a, r, c)}{where}"
                        f" ({count} non-finite input entr{'y' if count == 1 else 'ies'} in `{arg}`);"
                        " the outputs of those points are not finite"
                    )
        if message is None:
            hit = _first_bad(flat, keep)
            if hit is not None:
                r, c, count = hit
                name, entry = self._output_at(c)
                message = (
                    f"{self.path}: output `{name}{entry}` is {_entry(flat, r, c)} at row {r} from finite"
                    f" inputs ({count} non-finite output entr{'y' if count == 1 else 'ies'}): the point is"
                    " outside the model's domain or overflows"
                )
        if message is None:
            return
        if errors == "raise":
            raise ValueError(message)
        warnings.warn(message, NonFiniteWarning, stacklevel=4)

    def _output_at(self, col: int) -> Tuple[str, str]:
        j = 0
        for name, k in self.outputs:
            if col < j + k:
                return name, ("" if k == 1 else f"[{col - j}]")
            j += k
        return "?", ""

    def raw(self, *args, errors: str = "warn") -> np.ndarray:
        """Every output entry flattened in order: shape ``(N, total)`` (a
        masked array when an input is masked); ``errors`` as for a call."""
        flat, _, row_mask = self._evaluate(args, errors)
        if row_mask is None:
            return flat
        return np.ma.MaskedArray(flat, mask=np.repeat(row_mask[:, None], flat.shape[1], axis=1))

    def __call__(self, *args, errors: str = "warn") -> Dict[str, np.ndarray]:
        flat, single, row_mask = self._evaluate(args, errors)
        out: Dict[str, np.ndarray] = {}
        j = 0
        for name, k in self.outputs:
            block = flat[:, j] if k == 1 else flat[:, j : j + k]
            if row_mask is not None:
                mask = row_mask if k == 1 else np.repeat(row_mask[:, None], k, axis=1)
                block = np.ma.MaskedArray(block, mask=mask)
            if single:
                if row_mask is not None and row_mask[0]:
                    out[name] = np.ma.masked
                else:
                    out[name] = float(block[0]) if k == 1 else block[0]
            else:
                out[name] = block
            j += k
        return out

    def __repr__(self) -> str:
        args = ", ".join(f"{a}[{len(s)}]" for a, s in self.inputs)
        return f"<pegdyn.Function {self.path}({args})>"


_ALL = [Function(d["module"], d["name"], d["inputs"], d["outputs"]) for d in _core.functions()]


def functions() -> List[Function]:
    """Every generated function, in registry order."""
    return list(_ALL)


def function(module: str, name: str) -> Function:
    """The generated function ``module::name`` (KeyError if none)."""
    for f in _ALL:
        if f.module == module and f.name == name:
            return f
    raise KeyError(f"no generated function {module}::{name}")


#: ``generated.<module>.<name>``: every generated function by attribute.
generated = SimpleNamespace(
    **{
        m: SimpleNamespace(**{f.name: f for f in _ALL if f.module == m})
        for m in dict.fromkeys(f.module for f in _ALL)
    }
)
