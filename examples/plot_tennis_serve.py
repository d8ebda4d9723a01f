"""
A tennis serve's flight and bounces
===================================

:func:`spinimpact.flight` flies a spinning ball through the air (drag, Magnus lift, spin
decay), bounces it exactly on the ground preset, and lets it roll to rest. A first serve
hit at 50 m/s, 6 degrees down from 2.8 m, with 2000 rpm of topspin, on a hard court; the
same serve in a vacuum would land metres further. :func:`spinimpact.viz.flight.plot_flight`
draws the side and top views.
"""

import matplotlib.pyplot as plt

import spinimpact as si
from spinimpact.viz.flight import plot_flight

serve = si.flight(
    "tennis", "hard", speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0, max_bounces=3
)
print(serve.table())
vacuum = si.flight(
    "tennis",
    "hard",
    speed=50.0,
    angle=-6.0,
    height=2.8,
    spin_rpm=2000.0,
    max_bounces=1,
    air_density=0.0,
)
print(
    f"first bounce at {float(serve.bounces.position.x[0]):.2f} m in air, "
    f"{float(vacuum.bounces.position.x[0]):.2f} m in a vacuum"
)

fig = plot_flight(serve)
plt.show()
