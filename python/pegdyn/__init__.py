"""pegdyn from Python: peg-in-hole dynamics scenes, the generated model
functions evaluated on numpy arrays, and parameter sweeps run locally in
parallel or on a Dask cluster.

The same objects as the ``pegdyn`` command line, as Python values:

>>> import pegdyn
>>> scene = pegdyn.load("scenes/pendulum.toml")      # or loads(text), from_dict(d)
>>> result = scene.run()                              # in memory: columns, outcome, events, summary
>>> result.columns["theta_rad"][:3]                   # numpy arrays
>>> f = pegdyn.function("pendulum", "energy")         # a generated function
>>> f(states, params)                                 # one row per point
>>> pegdyn.sweep(scene, {"pendulum.theta0_deg": [10, 20, 30]})

Scenes that do not validate raise :class:`SceneError` (a ``ValueError``)
with the messages of ``pegdyn check`` and the offending ``field``,
``value`` and ``reason``.
"""

from ._pegdyn import RunError, SceneError, __version__
from ._scene import Event, Outcome, Result, Scene, from_dict, kinds, load, loads
from ._functions import Function, NonFiniteWarning, function, functions, generated
from ._sweep import SweepResult, sweep

__all__ = [
    "Event",
    "Function",
    "NonFiniteWarning",
    "Outcome",
    "Result",
    "RunError",
    "Scene",
    "SceneError",
    "SweepResult",
    "__version__",
    "from_dict",
    "function",
    "functions",
    "generated",
    "kinds",
    "load",
    "loads",
    "sweep",
]
