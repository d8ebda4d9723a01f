"""The impact hook in PyBullet: :class:`~spinimpact.engines.PybulletHook`, for ``stepSimulation``.

The hook reads the body and the plane from the user's PyBullet world: a body without
links whose collision shape is a sphere or a box, centred on its centre of mass, its
mass and inertia (``getDynamicsInfo``), and a plane body (``GEOM_PLANE``). While the hook
is open, the engine's contact between the two is switched off with
``setCollisionFilterPair``; :meth:`~spinimpact.engines.hook.Hook.close` switches it back
on. The state is written with ``resetBasePositionAndOrientation`` and ``resetBaseVelocity``.

Bullet applies linear and angular damping to a body by default (0.04): the hook refuses
a step in which the body's velocity changed by anything but gravity, so set both to 0
with ``changeDynamics`` (and lift ``maxJointVelocity``, 100 by default, above the body's
speeds). PyBullet keeps no clock: the times of
:class:`~spinimpact.engines.HookStep` and :class:`~spinimpact.engines.HookImpact` count
from the hook's creation.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._validation import require
from .hook import Geometry, Hook, Law, quat_matrix

__all__ = ["PybulletHook"]


def _wxyz(q) -> np.ndarray:
    """PyBullet's ``(x, y, z, w)`` quaternion as ``(w, x, y, z)``, normalised."""
    out = np.array([q[3], q[0], q[1], q[2]], float)
    return out / np.sqrt(out @ out)


def _id(name: str, value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise TypeError(f"{name} must be a PyBullet body id (an integer), got {value!r}")
    return int(value)


class PybulletHook(Hook):
    """Exact impacts of one body on one plane, inside a PyBullet world's own loop.

    Call :meth:`~spinimpact.engines.hook.Hook.step` where the loop called
    ``pybullet.stepSimulation()``: it takes the same step, and where the body reaches the
    plane within it, applies the exact impact at the contact instant (see
    :mod:`spinimpact.engines.hook`).

    Parameters
    ----------
    body : int
        The body's id: no links, its collision shape a sphere or a box, its inertial frame
        at its base's (``baseInertialFramePosition`` 0, no rotation).
    plane : int
        The id of a static body whose collision shape is a plane (``GEOM_PLANE``).
    mu, kappa, tangential, law, rest_speed
        As :class:`~spinimpact.engines.MujocoHook`'s.
    client : int
        The physics client id (``pybullet.connect``'s), default 0.

    Raises
    ------
    TypeError, ValueError
        Inputs of the wrong kind or value, or a body or plane the hook cannot take.
    ImportError
        If PyBullet is not installed.
    """

    def __init__(self, body: Any, plane: Any, *, mu: Any, kappa: Any, tangential: Any = None,
                 law: str = "poisson", rest_speed: Any = None,
                 client: Any = 0) -> None:  # fmt: skip
        pb = require("pybullet", "engines.PybulletHook")
        rules = Law.checked(mu, kappa, tangential, law, rest_speed)
        client = _id("client", client)
        if not pb.isConnected(physicsClientId=client):
            raise ValueError(f"client must be a connected PyBullet client, got {client!r}")
        kw = {"physicsClientId": client}
        b, p = _id("body", body), _id("plane", plane)
        ids = {pb.getBodyUniqueId(i, **kw) for i in range(pb.getNumBodies(**kw))}
        for name, value in (("body", b), ("plane", p)):
            if value not in ids:
                raise ValueError(f"{name} must be a body of client {client}, got {value!r}")
        if pb.getNumJoints(b, **kw):
            raise ValueError(f"body must have no links, got body {b} with links")
        self._pb, self._kw, self._body, self._plane = pb, kw, b, p
        geometry = self._geometry_of(pb, kw, b, p)
        self._setup(geometry, rules)
        self._steps = 0
        self._isotropic = bool(np.ptp(geometry.moments) == 0)
        self._vacant(("pybullet", kw.get("physicsClientId", 0)))
        pb.setCollisionFilterPair(b, p, -1, -1, 0, **kw)
        self._claim(("pybullet", kw.get("physicsClientId", 0)), _restorer(pb, kw, b, p))

    @staticmethod
    def _geometry_of(pb, kw, b, p) -> Geometry:
        info = pb.getDynamicsInfo(b, -1, **kw)
        mass, moments, inertial_pos, inertial_orn = info[0], info[2], info[3], info[4]
        shapes = pb.getCollisionShapeData(b, -1, **kw)
        if len(shapes) != 1:
            raise ValueError(f"body must have one collision shape, got {len(shapes)}")
        kind, dims, pos, orn = shapes[0][2], shapes[0][3], shapes[0][5], shapes[0][6]
        if np.any(inertial_pos) or np.any(np.array(inertial_orn) != (0, 0, 0, 1)) or np.any(pos):
            raise ValueError("body must have its inertial frame and its collision shape at "
                             "its base's origin")  # fmt: skip
        if kind == pb.GEOM_SPHERE:
            points, radii = np.zeros((1, 3)), np.array([dims[0]], float)
        elif kind == pb.GEOM_BOX:
            corners = np.array(np.meshgrid(*[[-0.5, 0.5]] * 3)).reshape(3, -1).T
            points = (corners * np.array(dims, float)) @ quat_matrix(_wxyz(orn)).T
            radii = np.zeros(8)
        else:
            raise ValueError(
                f"body must have a sphere or box shape, got {_shape_name(pb, kind)} (body {b})"
            )
        if mass <= 0:
            raise ValueError(f"body must have a mass > 0, got {mass!r}")
        plane = pb.getCollisionShapeData(p, -1, **kw)
        if len(plane) != 1 or plane[0][2] != pb.GEOM_PLANE:
            raise ValueError(f"plane must be a body whose one collision shape is a plane, "
                             f"got body {p}")  # fmt: skip
        if pb.getDynamicsInfo(p, -1, **kw)[0] != 0:
            raise ValueError(f"plane must be static (mass 0), got body {p}")
        where, turn = pb.getBasePositionAndOrientation(p, **kw)
        normal = quat_matrix(_wxyz(turn)) @ np.array(plane[0][3], float)
        return Geometry(
            mass=float(mass), moments=np.array(moments, float), axes=np.eye(3), points=points,
            radii=radii, origin=np.array(where, float), normal=normal / np.linalg.norm(normal),
        )  # fmt: skip

    # -- the engine's side of Hook ---------------------------------------------------------
    def _read(self):
        pb, kw = self._pb, self._kw
        x = pb.getBasePositionAndOrientation(self._body, **kw)[0]
        return np.array(x, float), np.array(pb.getBaseVelocity(self._body, **kw)[0], float)

    def _turning(self):
        pb, kw = self._pb, self._kw
        q = pb.getBasePositionAndOrientation(self._body, **kw)[1]
        return _wxyz(q), np.array(pb.getBaseVelocity(self._body, **kw)[1], float)

    def _write(self, x, v, q, w) -> None:
        pb, kw = self._pb, self._kw
        orn = [float(q[1]), float(q[2]), float(q[3]), float(q[0])]
        pb.resetBasePositionAndOrientation(self._body, x.tolist(), orn, **kw)
        pb.resetBaseVelocity(self._body, v.tolist(), w.tolist(), **kw)

    def _clock(self):
        par = self._pb.getPhysicsEngineParameters(**self._kw)
        if par["numSubSteps"] > 1:
            raise ValueError(f"the hook takes one step per stepSimulation; numSubSteps is "
                             f"{par['numSubSteps']}")  # fmt: skip
        span = float(par["fixedTimeStep"])
        g = np.array([par[f"gravityAcceleration{c}"] for c in "XYZ"], float)
        return self._steps * span, span, g

    def _save(self, impact: bool):
        """A saved world for an impact step (saving costs about a millisecond in PyBullet
        3.2.7, a hundred steps: a step without an impact is not saved)."""
        return self._pb.saveState(**self._kw) if impact else None

    def _restore(self, saved) -> bool:
        if saved is None:
            return False
        self._pb.restoreState(saved, **self._kw)
        self._pb.removeState(saved, **self._kw)
        self._steps -= 1
        return True

    def _discard(self, saved) -> None:
        if saved is not None:
            self._pb.removeState(saved, **self._kw)

    def _advance(self, v0, g, span) -> str | None:
        """The engine's step; the body flew free if its velocity changed by gravity's alone
        (to 1e-12 of the speeds) and, for isotropic inertia, its spin did not change."""
        pb, kw, b = self._pb, self._kw, self._body
        w0 = pb.getBaseVelocity(b, **kw)[1]
        pb.stepSimulation(**kw)
        self._steps += 1
        v, w = pb.getBaseVelocity(b, **kw)
        v0, g = v0.tolist(), g.tolist()
        tol = 1e-12 * (max(map(abs, v0)) + max(map(abs, g)) * span)
        if max(abs(a - (b0 + c * span)) for a, b0, c in zip(v, v0, g, strict=True)) > tol:
            return ("the body's velocity changed by more than gravity gives (a contact? "
                    "damping: set linearDamping to 0)")  # fmt: skip
        tol = 1e-12 * max(map(abs, w0))
        if self._isotropic and max(abs(a - b0) for a, b0 in zip(w, w0, strict=True)) > tol:
            return "the body's spin changed (a contact? damping: set angularDamping to 0)"
        return None


def _restorer(pb: Any, kw: dict, body: int, plane: int) -> Any:
    """A function that gives the body's contact with the plane back to PyBullet (it holds
    the client's id, not a hook); nothing to give back once the client is disconnected."""

    def release() -> None:
        try:
            pb.setCollisionFilterPair(body, plane, -1, -1, 1, **kw)
        except pb.error:
            pass

    return release


def _shape_name(pb: Any, kind: int) -> str:
    """PyBullet's name of a collision shape type (``GEOM_PLANE`` for 6)."""
    names = [n for n in dir(pb) if n.startswith("GEOM_") and getattr(pb, n) == kind]
    return names[0] if names else f"shape type {kind}"
