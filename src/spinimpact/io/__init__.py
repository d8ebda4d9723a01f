"""Files: atomic output, batch files of incidences, sweeps over grids and samples.

:func:`atomic_path` writes under a temporary name and renames only on success;
:mod:`spinimpact.io.batch` solves every row of a CSV/Parquet file in bounded
memory (the paper's bodies, or planar bodies and pendulums by their columns:
:mod:`spinimpact.io.planar_batch`); :mod:`spinimpact.io.sweep` evaluates grids and
random samples, locally or on a Dask cluster, for a paper body, and
:mod:`spinimpact.io.problem_sweep` for any registered problem (a sphere, a planar body or
pendulum, a body under a tangential law, two spheres).
"""

from .atomic import atomic_path

__all__ = ["atomic_path"]
