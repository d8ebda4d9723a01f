"""The impact hook in MuJoCo: :class:`~spinimpact.engines.MujocoHook`, for ``mj_step``.

The hook reads the body and the plane from the user's ``MjModel``: the body's free joint,
its collision geoms (spheres, capsules and boxes), its mass and principal inertia, and a
plane geom of the world body (MuJoCo's planes are infinite for collisions). While the hook
is open, the engine's own contact between this body and this plane is switched off through
the geoms' ``contype``/``conaffinity`` bits (the plane moves to a bit of its own, which
every other geom that collided with it gains in its ``conaffinity``);
:meth:`~spinimpact.engines.hook.Hook.close` puts the bits back. Contacts of the body
with anything else stay the engine's, and the hook refuses a step in which one acts (see
:mod:`spinimpact.engines.hook`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._validation import require
from .hook import Geometry, Hook, Law, quat_matrix

__all__ = ["MujocoHook"]


def _index(mj, model, kind: str, obj: Any, value: Any) -> int:
    """The id of the body or geom ``value`` (a name or an id)."""
    count = model.nbody if kind == "body" else model.ngeom
    if isinstance(value, str):
        found = mj.mj_name2id(model, obj, value)
        if found < 0:
            raise ValueError(f"{kind} must name a {kind} of the model, got {value!r}")
        return int(found)
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise TypeError(f"{kind} must be a {kind} name or id, got {value!r}")
    if not 0 <= value < count:
        raise ValueError(f"{kind} must be a {kind} id in [0, {count}), got {value!r}")
    return int(value)


class MujocoHook(Hook):
    """Exact impacts of one free body on one plane, inside a MuJoCo model's own loop.

    Call :meth:`~spinimpact.engines.hook.Hook.step` where the loop called
    ``mujoco.mj_step(model, data)``: it takes the same step, and where the body reaches
    the plane within it, applies the exact impact at the contact instant (see
    :mod:`spinimpact.engines.hook`).

    Parameters
    ----------
    model, data : mujoco.MjModel, mujoco.MjData
        The user's model and data.
    body : str or int
        The body (name or id): one free joint, no child bodies, its centre of mass at its
        frame's origin, its collision geoms spheres, capsules or boxes.
    mu, kappa : float
        Coulomb's friction coefficient (``>= 0``) and the coefficient of restitution
        (in ``[0, 1]``) of the exact law.
    plane : str or int, optional
        The plane geom (name or id), on the world body; by default the model's only plane.
    tangential : Walton, Stronge or MindlinDeresiewicz, optional
        A tangential compliance law, for a sphere (:func:`spinimpact.solve_sphere`'s).
    law : {"poisson", "newton", "energetic"}
        The restitution law of a body that is not a sphere (:func:`spinimpact.solve_rigid`).
    rest_speed : float, optional
        The slowest approach (m/s) taken as an impact; by default ``|g| h`` along the
        plane's normal, the speed gravity gives in one step. A slower one is refused.

    Raises
    ------
    TypeError, ValueError
        Inputs of the wrong kind or value, a body or plane the hook cannot take, a model
        with an explicit contact ``<pair>`` between the body and the plane, or no free
        ``contype`` bit left.
    ImportError
        If MuJoCo is not installed.
    """

    def __init__(self, model: Any, data: Any, body: Any, *, mu: Any, kappa: Any,
                 plane: Any = None, tangential: Any = None, law: str = "poisson",
                 rest_speed: Any = None) -> None:  # fmt: skip
        mj = require("mujoco", "engines.MujocoHook")
        if not isinstance(model, mj.MjModel):
            raise TypeError(f"model must be a mujoco.MjModel, got {type(model).__name__}")
        if not isinstance(data, mj.MjData):
            raise TypeError(f"data must be a mujoco.MjData, got {type(data).__name__}")
        rules = Law.checked(mu, kappa, tangential, law, rest_speed)
        b = _index(mj, model, "body", mj.mjtObj.mjOBJ_BODY, body)
        joint = int(model.body_jntadr[b])
        if model.body_jntnum[b] != 1 or model.jnt_type[joint] != mj.mjtJoint.mjJNT_FREE:
            raise ValueError(f"body must have one free joint and no other, got body {body!r}")
        if np.any(model.body_parentid[1:] == b):
            raise ValueError(f"body must have no child bodies, got body {body!r}")
        geoms = [
            i for i in range(model.ngeom)
            if model.geom_bodyid[i] == b and (model.geom_contype[i] or model.geom_conaffinity[i])
        ]  # fmt: skip
        if not geoms:
            raise ValueError(f"body must have a collision geom, got body {body!r}")
        p = self._plane(mj, model, plane)
        self._mj, self._model, self._data, self._body = mj, model, data, b
        self._qpos, self._qvel = int(model.jnt_qposadr[joint]), int(model.jnt_dofadr[joint])
        geometry = self._geometry_of(mj, model, b, geoms, p)
        for i in range(model.npair):
            pair = {int(model.pair_geom1[i]), int(model.pair_geom2[i])}
            if p in pair and pair & set(geoms):
                raise ValueError(
                    "the model has an explicit contact <pair> between the body and the "
                    "plane, which the hook cannot switch off: remove it"
                )
        self._vacant(id(model))
        self._setup(geometry, rules)
        self._spec = mj.mjtState.mjSTATE_INTEGRATION
        self._buffer = np.empty(mj.mj_stateSize(model, self._spec))
        self._claim(id(model), _restorer(model, self._exclude(model, geoms, p)))

    # -- reading the model ---------------------------------------------------------------
    @staticmethod
    def _plane(mj, model, plane) -> int:
        planes = np.flatnonzero(model.geom_type == mj.mjtGeom.mjGEOM_PLANE)
        if plane is None:
            if planes.size != 1:
                raise ValueError(f"plane must be given: the model has {planes.size} plane geoms")
            p = int(planes[0])
        else:
            p = _index(mj, model, "plane", mj.mjtObj.mjOBJ_GEOM, plane)
            if p not in planes:
                raise ValueError(f"plane must be a plane geom, got {plane!r}")
        if model.geom_bodyid[p] != 0:
            raise ValueError(f"plane must be a geom of the world body, got {plane!r}")
        return p

    @staticmethod
    def _geometry_of(mj, model, b, geoms, p) -> Geometry:
        size = float(np.max(model.geom_rbound[geoms]))
        if np.max(np.abs(model.body_ipos[b])) > 1e-12 * size:
            raise ValueError("body must have its centre of mass at its frame's origin "
                             f"(body_ipos = 0), got {model.body_ipos[b].tolist()}")  # fmt: skip
        kinds = mj.mjtGeom
        points, radii = [], []
        for i in geoms:
            pos, axes, half = model.geom_pos[i], quat_matrix(model.geom_quat[i]), model.geom_size[i]
            if model.geom_type[i] == kinds.mjGEOM_SPHERE:
                points.append(pos), radii.append(half[0])
            elif model.geom_type[i] == kinds.mjGEOM_CAPSULE:
                for end in (-1.0, 1.0):
                    points.append(pos + end * half[1] * axes[:, 2]), radii.append(half[0])
            elif model.geom_type[i] == kinds.mjGEOM_BOX:
                for corner in np.array(np.meshgrid(*[[-1.0, 1.0]] * 3)).reshape(3, -1).T:
                    points.append(pos + axes @ (corner * half)), radii.append(0.0)
            else:
                name = kinds(int(model.geom_type[i])).name
                raise ValueError(f"the hook takes sphere, capsule and box geoms; geom {i} of "
                                 f"the body is a {name}")  # fmt: skip
        plane_axes = quat_matrix(model.geom_quat[p])
        return Geometry(
            mass=float(model.body_mass[b]), moments=np.array(model.body_inertia[b], float),
            axes=quat_matrix(model.body_iquat[b]), points=np.array(points, float),
            radii=np.array(radii, float), origin=np.array(model.geom_pos[p], float),
            normal=plane_axes[:, 2].copy(),
        )  # fmt: skip

    @staticmethod
    def _exclude(model, geoms, p) -> tuple[np.ndarray, np.ndarray]:
        """Switch the engine's contact between ``geoms`` and the plane ``p`` off; return
        the bits to restore."""
        kept = model.geom_contype.copy(), model.geom_conaffinity.copy()
        used = int(np.bitwise_or.reduce(np.concatenate(kept)))
        free = next((1 << k for k in range(32) if not used & (1 << k)), None)
        if free is None:
            raise ValueError("no contype bit is free: the hook needs one of the 32 for the plane")
        ct, ca = kept
        for i in range(model.ngeom):
            if i != p and i not in geoms and (ct[i] & ca[p] or ct[p] & ca[i]):
                model.geom_conaffinity[i] = ca[i] | free
        model.geom_contype[p] = free
        model.geom_conaffinity[p] = free
        return kept

    # -- the engine's side of Hook ---------------------------------------------------------
    def _read(self):
        d, a, dv = self._data, self._qpos, self._qvel
        return d.qpos[a : a + 3].copy(), d.qvel[dv : dv + 3].copy()

    def _turning(self):
        d, a, dv = self._data, self._qpos, self._qvel
        q = d.qpos[a + 3 : a + 7].copy()
        q /= np.sqrt(q @ q)
        return q, quat_matrix(q) @ d.qvel[dv + 3 : dv + 6]

    def _write(self, x, v, q, w) -> None:
        d, a, dv = self._data, self._qpos, self._qvel
        d.qpos[a : a + 3] = x
        d.qpos[a + 3 : a + 7] = q
        d.qvel[dv : dv + 3] = v
        d.qvel[dv + 3 : dv + 6] = quat_matrix(q).T @ w

    def _clock(self):
        m = self._model
        return float(self._data.time), float(m.opt.timestep), np.array(m.opt.gravity)

    def _save(self, impact: bool):
        self._mj.mj_getState(self._model, self._data, self._buffer, self._spec)
        return self._buffer

    def _restore(self, saved) -> bool:
        self._mj.mj_setState(self._model, self._data, saved, self._spec)
        return True

    def _discard(self, saved) -> None:
        pass

    def _advance(self, v, g, span) -> str | None:
        """The engine's step; the body flew free if no constraint acted on its dofs and its
        smooth force was gravity's and the velocity products' alone: ``qfrc_smooth`` is
        ``qfrc_passive - qfrc_bias + qfrc_applied + qfrc_actuator`` plus ``xfrc_applied``
        mapped to the dofs, so ``qfrc_smooth + qfrc_bias`` is exactly 0 then."""
        d, dofs = self._data, slice(self._qvel, self._qvel + 6)
        self._mj.mj_step(self._model, d)
        if np.count_nonzero(d.qfrc_constraint[dofs]):
            return "the body felt a constraint force (a contact with another body, a limit)"
        if np.count_nonzero(d.qfrc_smooth[dofs] + d.qfrc_bias[dofs]):
            return ("the body felt a force other than gravity (xfrc_applied, qfrc_applied, an "
                    "actuator, damping, a fluid)")  # fmt: skip
        return None


def _restorer(model: Any, bits: tuple[np.ndarray, np.ndarray]) -> Any:
    """A function that puts the geoms' contact bits back (it holds the model, not a hook)."""

    def release() -> None:
        model.geom_contype[:], model.geom_conaffinity[:] = bits

    return release
