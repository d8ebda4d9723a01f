"""The impact hooks (MujocoHook, PybulletHook) against a reference computed from the launch.

For each installed engine, random spinning balls are launched above a floor and stepped
with the hook through their first bounce and a few steps more; the reference is computed
here without the hook's code: the closed-form parabola to the contact, the exact bounce
(:func:`spinimpact.solve_sphere`) and the parabola after. A cube dropped on a corner is
checked the same way, its contact found by SciPy's ``brentq`` on the lowest corner's height
along the exact flight (isotropic inertia: constant spin) and its bounce by
:func:`spinimpact.solve_rigid`. Printed per engine:

* the largest error of velocity and spin after the bounce, over the speed scale
  ``max(|v|, R |w|)`` at the contact;
* the engine's position error (its semi-implicit Euler integration since the impact step,
  predicted as ``g h^2 N / 2`` after ``N`` steps) and how far it is from that prediction;
* the cost: the engine's own step, the hook's step without an impact and with one, as
  ratios to the engine's step, all measured in the same run.

Run with ``.venv/bin/python -m benchmarks.engine_hook`` from the repository root
(``--balls 1000 --cubes 100`` by default). ``tests/engines/test_hook.py`` uses the same
scenes with fewer cases.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from spinimpact import Body, RigidBody, Surface, solve_rigid, solve_sphere
from spinimpact import engines as E

G = 9.81
DOWN = np.array([0.0, 0.0, -G])
FLOOR = Surface(normal=(0.0, 0.0, 1.0))
RADIUS, MASS = 0.1, 1.0  #: the ball, m and kg (a solid sphere)
HALF, CUBE_MASS = 0.05, 0.5  #: the cube's half side (m) and mass (kg)
BALL = Body(mass=MASS, radius=RADIUS, gyration=RADIUS * np.sqrt(0.4))
CUBE_INERTIA = CUBE_MASS * (2 * HALF) ** 2 / 6  #: kg m^2 about any axis


def rotation(q) -> np.ndarray:
    """The rotation matrix of a quaternion (w, x, y, z), by SciPy."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_quat(np.asarray(q) / np.linalg.norm(q), scalar_first=True).as_matrix()


class MujocoScene:
    """A floor and one free ball or cube in one MuJoCo model, relaunched for every case."""

    def __init__(self, shape: str = "ball", timestep: float = 0.002):
        import mujoco

        self.mj = mujoco
        geom = (
            f'type="sphere" size="{RADIUS}" mass="{MASS}"'
            if shape == "ball"
            else f'type="box" size="{HALF} {HALF} {HALF}" mass="{CUBE_MASS}"'
        )
        xml = (
            f'<mujoco><option timestep="{timestep}" gravity="0 0 {-G}"/><worldbody>'
            '<geom name="floor" type="plane" size="0 0 1"/><body name="body" pos="0 0 1">'
            f"<freejoint/><geom {geom}/></body></worldbody></mujoco>"
        )
        self.model = mujoco.MjModel.from_xml_string(xml)
        self.data = mujoco.MjData(self.model)
        self.timestep = timestep

    def launch(self, x, q, v, w, **law):
        self.mj.mj_resetData(self.model, self.data)
        d = self.data
        d.qpos[:3], d.qpos[3:], d.qvel[:3] = x, q, v
        d.qvel[3:] = rotation(q).T @ np.asarray(w)  # MuJoCo's spin is in the body's frame
        return E.MujocoHook(self.model, self.data, "body", **law)

    def state(self):
        d = self.data
        return d.qpos[:3].copy(), d.qvel[:3].copy(), rotation(d.qpos[3:]) @ d.qvel[3:]

    def engine_step(self) -> None:
        self.mj.mj_step(self.model, self.data)

    def close(self) -> None:
        pass


class PybulletScene:
    """A plane and one ball or cube in one PyBullet world with gravity, relaunched for
    every case (no damping, no velocity clamp, the inertia of a solid sphere or cube)."""

    def __init__(self, shape: str = "ball", timestep: float = 1.0 / 240.0):
        import pybullet as pb

        self.pb = pb
        self.client = pb.connect(pb.DIRECT)
        kw = self.kw = {"physicsClientId": self.client}
        self.timestep = timestep
        pb.setGravity(0, 0, -G, **kw)
        pb.setTimeStep(timestep, **kw)
        self.plane = pb.createMultiBody(0, pb.createCollisionShape(pb.GEOM_PLANE, **kw), **kw)
        if shape == "ball":
            made = pb.createCollisionShape(pb.GEOM_SPHERE, radius=RADIUS, **kw)
            mass, inertia = MASS, 0.4 * MASS * RADIUS**2
        else:
            made = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=[HALF] * 3, **kw)
            mass, inertia = CUBE_MASS, CUBE_INERTIA
        self.body = pb.createMultiBody(mass, made, basePosition=[0, 0, 1], **kw)
        pb.changeDynamics(
            self.body, -1, linearDamping=0.0, angularDamping=0.0, maxJointVelocity=1e30,
            localInertiaDiagonal=[inertia] * 3, **kw,
        )  # fmt: skip

    def launch(self, x, q, v, w, **law):
        pb, kw = self.pb, self.kw
        xyzw = [q[1], q[2], q[3], q[0]]
        pb.resetBasePositionAndOrientation(self.body, list(x), xyzw, **kw)
        pb.resetBaseVelocity(self.body, list(v), list(w), **kw)
        return E.PybulletHook(self.body, self.plane, client=self.client, **law)

    def state(self):
        pb, kw = self.pb, self.kw
        v, w = pb.getBaseVelocity(self.body, **kw)
        x = pb.getBasePositionAndOrientation(self.body, **kw)[0]
        return np.array(x), np.array(v), np.array(w)

    def engine_step(self) -> None:
        self.pb.stepSimulation(**self.kw)

    def close(self) -> None:
        self.pb.disconnect(self.client)


SCENES = {"mujoco": MujocoScene, "pybullet": PybulletScene}


def random_launches(n: int, seed: int, height=(0.02, 1.0), spin=150.0):
    """``n`` random launches: centre heights above touching, velocities (m/s), spins
    (rad/s), random orientations (w, x, y, z), ``mu`` in [0, 0.8], ``kappa`` in [0.3, 0.95]."""
    rng = np.random.default_rng(seed)
    x = np.zeros((n, 3))
    x[:, :2] = rng.uniform(-1, 1, (n, 2))
    x[:, 2] = rng.uniform(*height, n)
    v = rng.uniform(-3, 3, (n, 3))
    v[:, 2] = rng.uniform(-4, 2, n)
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    w = rng.uniform(-spin, spin, (n, 3))
    return x, q, v, w, rng.uniform(0, 0.8, n), rng.uniform(0.3, 0.95, n)


def ball_reference(x, v, w, mu, kappa, t):
    """Velocity, spin and position at time ``t`` of a ball launched at time 0 (the closed
    form and solve_sphere), the contact time and the speed scale at the contact."""
    tc = (v[2] + np.sqrt(v[2] ** 2 + 2 * G * (x[2] - RADIUS))) / G
    vc = v + DOWN * tc
    exact = solve_sphere(BALL, vc, w, mu=mu, kappa=kappa, surface=FLOOR)
    after = t - tc
    v1 = np.asarray(exact.after.velocity)
    x1 = x + v * tc + 0.5 * DOWN * tc**2 + v1 * after + 0.5 * DOWN * after**2
    speed = max(np.linalg.norm(vc), RADIUS * np.linalg.norm(w))
    return v1 + DOWN * after, np.asarray(exact.after.spin), x1, tc, speed


def cube_reference(x, q, v, w, mu, kappa, t):
    """The first corner impact of a cube launched at time 0, found on the exact flight
    (brentq on the lowest corner) and solved by solve_rigid: the contact time, the contact
    point, the velocity and spin after, and the speed scale at the contact."""
    from scipy.optimize import brentq
    from scipy.spatial.transform import Rotation

    corners = HALF * np.array(np.meshgrid(*[[-1.0, 1.0]] * 3)).reshape(3, -1).T
    turn = Rotation.from_quat(q, scalar_first=True)

    def lowest(s):
        arms = (Rotation.from_rotvec(w * s) * turn).apply(corners)
        return x[2] + v[2] * s - 0.5 * G * s * s + np.min(arms[:, 2])

    grid = np.linspace(0, t, 400)
    k = int(np.argmax([lowest(s) < 0 for s in grid]))
    tc = brentq(lowest, grid[k - 1], grid[k], xtol=1e-16, rtol=1e-15)
    arms = (Rotation.from_rotvec(w * tc) * turn).apply(corners)
    arm = arms[np.argmin(arms[:, 2])]
    body = RigidBody(CUBE_MASS, CUBE_INERTIA * np.eye(3), arm)
    vc = v + DOWN * tc
    exact = solve_rigid(body, vc, w, mu=mu, kappa=kappa, surface=FLOOR)
    speed = max(np.linalg.norm(vc), np.sqrt(3) * HALF * np.linalg.norm(w))
    point = x + v * tc + 0.5 * DOWN * tc**2 + arm
    return tc, point, exact.velocity, exact.spin, speed


def through_impact(scene, launch, after: int):
    """Step a launched body with its hook through its first impact step and ``after``
    steps more: the steps taken, the impact step's number and output, the last output,
    and the wall time of each hook step (s) with whether it held an impact."""
    x, q, v, w, mu, kappa = launch
    hook = scene.launch(x, q, v, w, mu=mu, kappa=kappa)
    steps, hit, first, timings = 0, None, None, []
    while hit is None or steps < hit + after:
        start = time.perf_counter()
        out = hook.step()
        timings.append((time.perf_counter() - start, out.impacted))
        steps += 1
        if out.impacted and hit is None:
            hit, first = steps, out
    hook.close()
    return steps, hit, first, out, timings


def balls(engine: str, n: int, seed: int = 1) -> dict:
    """``n`` random spinning balls through their bounce: errors and timings."""
    scene = SCENES[engine]()
    h = scene.timestep
    rows = {"error": [], "drift": [], "euler": [], "flight_s": [], "impact_s": [], "law_s": []}
    try:
        cases = random_launches(n, seed)
        cases[0][:, 2] += RADIUS
        after = np.random.default_rng(seed + 1).integers(1, 20, n)
        for k, launch in enumerate(zip(*cases, strict=True)):
            steps, hit, first, _, timings = through_impact(scene, launch, int(after[k]))
            x, _, v, w, mu, kappa = launch
            v_ref, w_ref, x_ref, _, speed = ball_reference(x, v, w, mu, kappa, steps * h)
            position, velocity, spin = scene.state()
            err = max(np.max(np.abs(velocity - v_ref)), RADIUS * np.max(np.abs(spin - w_ref)))
            rows["error"].append(err / speed)
            rows["drift"].append(np.max(np.abs(position - x_ref)))
            rows["euler"].append(abs(position[2] - x_ref[2] + 0.5 * G * h * h * (steps - hit)))
            rows["flight_s"] += [t for t, hit_now in timings if not hit_now]
            rows["impact_s"] += [t for t, hit_now in timings if hit_now]
            hit_state = first.impacts[0]
            start = time.perf_counter()
            solve_sphere(BALL, hit_state.velocity_before, hit_state.spin_before, mu=mu,
                         kappa=kappa, surface=FLOOR)  # fmt: skip
            rows["law_s"].append(time.perf_counter() - start)
    finally:
        scene.close()
    return {k: np.array(v) for k, v in rows.items()}


def cubes(engine: str, n: int, seed: int = 2) -> dict:
    """``n`` spinning cubes dropped on a corner: the first impact against the reference."""
    scene = SCENES[engine]("cube")
    rows = {"error": [], "time": [], "point": [], "impact_s": [], "law_s": [], "two": 0}
    try:
        for launch in zip(*random_launches(n, seed, height=(0.15, 0.6), spin=30.0), strict=True):
            steps, _, first, _, timings = through_impact(scene, launch, 0)
            tc, point, v1, w1, speed = cube_reference(*launch, steps * scene.timestep)
            hit = first.impacts[0]
            err = max(np.max(np.abs(hit.velocity_after - v1)),
                      np.sqrt(3) * HALF * np.max(np.abs(hit.spin_after - w1)))  # fmt: skip
            rows["error"].append(err / speed)
            rows["time"].append(abs(hit.time - tc))
            rows["point"].append(np.max(np.abs(hit.point - point)))
            rows["impact_s"] += [t for t, hit_now in timings if hit_now]
            rows["two"] += len(first.impacts) > 1
            body = RigidBody(CUBE_MASS, CUBE_INERTIA * np.eye(3), hit.point - hit.position)
            start = time.perf_counter()
            solve_rigid(body, hit.velocity_before, hit.spin_before, mu=launch[4],
                        kappa=launch[5], surface=FLOOR)  # fmt: skip
            rows["law_s"].append(time.perf_counter() - start)
    finally:
        scene.close()
    return {k: np.array(v) for k, v in rows.items()}


def engine_step_seconds(engine: str, steps: int = 20_000, repeat: int = 5) -> tuple:
    """The engine's own step of the ball scene, in flight far above the floor, s (best of
    ``repeat`` runs), and for PyBullet the cost of saving and dropping its world (the hook
    saves it before a step with an impact), s (best of 50)."""
    scene = SCENES[engine]()
    try:
        scene.launch([0, 0, 1e6], [1, 0, 0, 0], [0, 0, 0], [0, 0, 0], mu=0.3, kappa=0.5).close()
        best = np.inf
        for _ in range(repeat):
            start = time.perf_counter()
            for _ in range(steps):
                scene.engine_step()
            best = min(best, (time.perf_counter() - start) / steps)
        save = np.nan
        if engine == "pybullet":
            pb, kw = scene.pb, scene.kw
            runs = []
            for _ in range(50):
                start = time.perf_counter()
                pb.removeState(pb.saveState(**kw), **kw)
                runs.append(time.perf_counter() - start)
            save = min(runs)
    finally:
        scene.close()
    return best, save


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--balls", type=int, default=1000)
    parser.add_argument("--cubes", type=int, default=100)
    args = parser.parse_args(argv)
    for engine in SCENES:  # the engines with an impact hook
        if not E.available(engine):
            print(f"{engine}: not installed, skipped")
            continue
        step, save = engine_step_seconds(engine)
        b = balls(engine, args.balls)
        c = cubes(engine, args.cubes)
        print(f"\n{engine} (time step {SCENES[engine]().timestep:g} s)")
        print(f"  {args.balls} balls: velocity and spin after the bounce vs the reference, "
              f"over the speed scale: max {b['error'].max():.2e}, "
              f"median {np.median(b['error']):.2e}")  # fmt: skip
        print(f"  position error (the engine's Euler since the impact step): max "
              f"{b['drift'].max():.2e} m; its distance from g h^2 N / 2: max "
              f"{b['euler'].max():.2e} m")  # fmt: skip
        print(f"  {args.cubes} cubes on a corner: velocity and spin after vs brentq + "
              f"solve_rigid, over the speed scale: max {c['error'].max():.2e}; contact time "
              f"max {c['time'].max():.2e} s; contact point max {c['point'].max():.2e} m; "
              f"{int(c['two'])} steps held a second corner impact")  # fmt: skip
        flight, impact = np.median(b["flight_s"]), np.median(b["impact_s"])
        cube, ball_law, cube_law = (np.median(a) for a in (c["impact_s"], b["law_s"], c["law_s"]))
        print(f"  cost (medians): the engine's step {step * 1e6:.1f} us; the hook's step "
              f"without an impact {flight * 1e6:.1f} us ({flight / step:.1f} x the engine's "
              f"step); with a ball's impact {impact * 1e6:.0f} us ({impact / step:.0f} x), of "
              f"which solve_sphere {ball_law * 1e6:.0f} us; with a cube's {cube * 1e3:.2f} ms "
              f"({cube / step:.0f} x), of which solve_rigid {cube_law * 1e3:.2f} ms")  # fmt: skip
        if engine == "pybullet":
            print(f"  (a step with an impact saves PyBullet's world first: "
                  f"{save * 1e6:.0f} us, {save / step:.0f} x the engine's step)")  # fmt: skip


if __name__ == "__main__":
    main()
