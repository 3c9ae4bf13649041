"""The generated model functions, evaluated on numpy arrays in a Rust loop."""

from __future__ import annotations

from types import SimpleNamespace
from typing import Dict, List, Tuple

import numpy as np

from . import _pegdyn as _core


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

    def _arrays(self, args) -> Tuple[List[np.ndarray], bool]:
        if len(args) != len(self.inputs):
            names = ", ".join(a for a, _ in self.inputs)
            raise TypeError(f"{self.path}: takes {len(self.inputs)} inputs ({names}), got {len(args)}")
        out = []
        single = True
        for (arg, syms), x in zip(self.inputs, args):
            a = np.asarray(x)
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
            out.append(np.ascontiguousarray(a, dtype=np.float64))
        return out, single

    def raw(self, *args) -> np.ndarray:
        """Every output entry flattened in order: shape ``(N, total)``."""
        arrays, _ = self._arrays(args)
        return _core.evaluate(self.module, self.name, arrays)

    def __call__(self, *args) -> Dict[str, np.ndarray]:
        arrays, single = self._arrays(args)
        flat = _core.evaluate(self.module, self.name, arrays)
        out: Dict[str, np.ndarray] = {}
        j = 0
        for name, k in self.outputs:
            block = flat[:, j] if k == 1 else flat[:, j : j + k]
            out[name] = (float(block[0]) if k == 1 else block[0]) if single else block
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
