"""
A batch file of impacts
=======================

:func:`spinimpact.io.batch.run_batch` solves every row of a CSV or Parquet file, in chunks
of bounded memory, and writes the inputs and every result column beside them (the CSV's
units go to a side file, ``out.units.json``). It is what ``spinimpact batch in.csv --output
out.csv`` runs. Here a file of 200 incidences of a solid sphere, with ``mu``, ``kappa`` and
the body given as defaults for the columns the file lacks.
"""

import csv
import json
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from spinimpact.io.batch import run_batch

folder = Path(tempfile.mkdtemp())
rng = np.random.default_rng(3)
rows = np.column_stack(
    [rng.uniform(0.0, 4.0, 200), np.full(200, -2.0), rng.uniform(-60.0, 60.0, 200)]
)
with open(folder / "in.csv", "w", newline="") as f:
    writer = csv.writer(f)
    writer.writerow(["vx", "vy", "omega"])
    writer.writerows(rows.tolist())

summary = run_batch(
    folder / "in.csv",
    folder / "out.csv",
    defaults={"mu": 0.3, "kappa": 0.8, "mass": 0.06, "radius": 0.033, "body": "solid-sphere"},
)
print(summary)
with open(folder / "out.csv", newline="") as f:
    table = list(csv.DictReader(f))
out = {name: np.array([row[name] for row in table]) for name in table[0]}
for name in ("vx", "omega", "after_vx"):
    out[name] = out[name].astype(float)
units = json.loads((folder / "out.units.json").read_text())
print(len(table), "rows; columns:", ", ".join(list(out)[:8]), "...")
print("units:", {k: units["units"][k] for k in ("vx", "omega", "after_vx", "dissipated_energy")})

fig, ax = plt.subplots(figsize=(6.4, 3.8), layout="constrained")
for regime in np.unique(out["regime"]):
    pick = out["regime"] == regime
    ax.plot(out["vx"][pick] + 0.033 * out["omega"][pick], out["after_vx"][pick], ".", label=regime)
ax.set_xlabel("slip before $u = v_x + R\\omega$, m/s")
ax.set_ylabel("$v_x$ after, m/s")
ax.legend()
plt.show()
