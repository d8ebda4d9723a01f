"""The impact in time: compliant contact laws that converge to the rigid-body solution.

>>> from spinimpact.dynamics import simulate, LinearContact, HertzContact, HuntCrossleyContact
"""

from .model.contact import (
    ContactLaw,
    HertzContact,
    HuntCrossleyContact,
    LinearContact,
    NormalImpact,
)
from .model.dynamics import Simulation, simulate
from .model.mindlin import Mindlin, TangentialSimulation

__all__ = [
    "ContactLaw",
    "HertzContact",
    "HuntCrossleyContact",
    "LinearContact",
    "Mindlin",
    "NormalImpact",
    "Simulation",
    "TangentialSimulation",
    "simulate",
]
