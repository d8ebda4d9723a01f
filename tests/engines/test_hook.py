"""spinimpact.engines.MujocoHook and PybulletHook: exact impacts inside the engines' loops.

The reference is computed from the launch state alone, without the hook's code
(``benchmarks/engine_hook.py``, which runs the same comparison on 1,000 balls): the
closed-form parabola to the contact (a root of the centre's height for a ball, of the
lowest corner's for a turning cube, by SciPy's brentq), the law (:func:`spinimpact.solve_sphere`,
:func:`spinimpact.solve_rigid`) and the parabola after.
"""

import numpy as np
import pytest
from benchmarks.engine_hook import (
    BALL,
    DOWN,
    FLOOR,
    HALF,
    RADIUS,
    SCENES,
    G,
    ball_reference,
    cube_reference,
    random_launches,
    rotation,
    through_impact,
)

from spinimpact import RigidBody, Walton, solve_rigid, solve_sphere
from spinimpact import engines as E

from .bodies import needs


def mujoco_ball():
    import mujoco

    xml = (
        f'<mujoco><option gravity="0 0 {-G}"/><worldbody>'
        '<geom name="floor" type="plane" size="0 0 1"/>'
        f'<body name="ball" pos="0 0 1"><freejoint/><geom type="sphere" size="{RADIUS}"/>'
        "</body></worldbody></mujoco>"
    )
    model = mujoco.MjModel.from_xml_string(xml)
    return model, mujoco.MjData(model)


def mujoco_box(half, mass=0.5):
    import mujoco

    xml = (
        f'<mujoco><option timestep="0.002" gravity="0 0 {-G}"/><worldbody>'
        '<geom name="floor" type="plane" size="0 0 1"/><body name="box" pos="0 0 1">'
        f'<freejoint/><geom type="box" size="{half[0]} {half[1]} {half[2]}" mass="{mass}"/>'
        "</body></worldbody></mujoco>"
    )
    model = mujoco.MjModel.from_xml_string(xml)
    return mujoco, model, mujoco.MjData(model)


@pytest.fixture
def ball(engine):
    if engine not in SCENES:
        pytest.skip(f"no impact hook for {engine}")
    world = SCENES[engine]()
    yield world
    world.close()


@pytest.fixture
def cube(engine):
    if engine not in SCENES:
        pytest.skip(f"no impact hook for {engine}")
    world = SCENES[engine]("cube")
    yield world
    world.close()


UPRIGHT = [1.0, 0.0, 0.0, 0.0]


@pytest.mark.slow
def test_balls_bounce_as_the_exact_flight_and_law(ball):
    """50 random spinning balls: after the bounce, velocity and spin agree with the
    reference computed from the launch to 1e-9 of the speed scale (rounding is about
    1e-15); the position carries only the engine's semi-implicit Euler error since the
    impact step, g h^2 N / 2 after N steps, which the hook reports as its drift."""
    h = ball.timestep
    cases = random_launches(50, seed=11)
    cases[0][:, 2] += RADIUS
    for launch in zip(*cases, strict=True):
        steps, hit, first, last, _ = through_impact(ball, launch, after=5)
        x, _, v, w, mu, kappa = launch
        v_ref, w_ref, x_ref, tc, speed = ball_reference(x, v, w, mu, kappa, steps * h)
        position, velocity, spin = ball.state()
        assert np.max(np.abs(velocity - v_ref)) <= 1e-9 * speed
        assert RADIUS * np.max(np.abs(spin - w_ref)) <= 1e-9 * speed
        assert abs(first.impacts[0].time - tc) <= 1e-12
        euler = -0.5 * G * h * h * (steps - hit)
        np.testing.assert_allclose(position - x_ref, [0, 0, euler], rtol=0, atol=1e-12)
        np.testing.assert_allclose(last.drift, [0, 0, euler], rtol=0, atol=1e-12)


@pytest.mark.slow
def test_cube_corner_impact_matches_the_rigid_body_law(cube):
    """Spinning cubes dropped on a corner (their flight is exact: isotropic inertia keeps
    the spin constant): the contact instant and point, and the velocity and spin after
    the impact, agree with solve_rigid at the contact found from the launch, to 1e-9 of
    the speed scale; so does the state the engine holds after a step of one impact."""
    for launch in zip(*random_launches(8, seed=5, height=(0.15, 0.6), spin=30.0), strict=True):
        steps, _, first, _, _ = through_impact(cube, launch, after=0)
        t = steps * cube.timestep
        tc, point, v1, w1, speed = cube_reference(*launch, t)
        hit = first.impacts[0]
        assert abs(hit.time - tc) <= 1e-12
        np.testing.assert_allclose(hit.point, point, rtol=0, atol=1e-12)
        assert np.max(np.abs(hit.velocity_after - v1)) <= 1e-9 * speed
        assert np.sqrt(3) * HALF * np.max(np.abs(hit.spin_after - w1)) <= 1e-9 * speed
        if len(first.impacts) == 1:  # (a second corner may strike within the same step)
            _, velocity, spin = cube.state()
            assert np.max(np.abs(velocity - (v1 + DOWN * (t - tc)))) <= 1e-9 * speed
            assert np.sqrt(3) * HALF * np.max(np.abs(spin - w1)) <= 1e-9 * speed


def test_box_impact_is_the_rigid_law_at_the_hooks_contact():
    """A box of three different sides, tumbling: the velocity change the hook applies is
    solve_rigid's for the state at its contact (the inertia turned to the orientation
    there), to rounding, and the corner leaves the plane."""
    needs("mujoco")
    from scipy.spatial.transform import Rotation

    mj, model, data = mujoco_box([0.03, 0.05, 0.08])
    rng = np.random.default_rng(8)
    moments = model.body_inertia[1]
    for _ in range(5):
        mj.mj_resetData(model, data)
        data.qpos[2] = 0.4
        data.qpos[3:] = Rotation.random(random_state=rng).as_quat(scalar_first=True)
        data.qvel[:] = rng.uniform(-10, 10, 6)
        data.qvel[2] = -2.0
        with E.MujocoHook(model, data, 1, mu=0.4, kappa=0.7, law="newton") as hook:
            out = hook.step()
            while not out.impacted:
                out = hook.step()
        hit = out.impacts[0]
        turn = rotation(hit.orientation)
        body = RigidBody(0.5, turn @ np.diag(moments) @ turn.T, hit.point - hit.position)
        exact = solve_rigid(body, hit.velocity_before, hit.spin_before, mu=0.4, kappa=0.7,
                            law="newton", surface=FLOOR)  # fmt: skip
        speed = np.linalg.norm(hit.velocity_before) + 0.1 * np.linalg.norm(hit.spin_before)
        assert np.max(np.abs(exact.velocity - hit.velocity_after)) <= 1e-12 * speed
        assert 0.1 * np.max(np.abs(exact.spin - hit.spin_after)) <= 1e-12 * speed
        assert float(hit.exact.contact_after.z) > 0  # the corner leaves the plane
        assert abs(hit.point[2]) <= 1e-12  # the contact is on the plane


# -- where the hook is not valid, and bad input --------------------------------------------
def test_resting_contact_is_refused_and_the_state_kept(ball):
    """A ball resting on the floor, or arriving too slowly, is refused with a ValueError
    before the engine steps; kappa = 0 leaves a ball resting after its impact: refused."""
    for x, v, words in [
        ([0, 0, RADIUS], [1.0, 0, 0], "resting contact"),  # rolling on the floor
        ([0, 0, RADIUS + 1e-7], [0, 0, -1e-4], "not faster than rest_speed"),
        ([0, 0, RADIUS - 1e-3], [0, 0, -1.0], "inside the plane"),
    ]:
        hook = ball.launch(x, UPRIGHT, v, [0, 0, 0], mu=0.3, kappa=0.5)
        before = ball.state()
        with pytest.raises(ValueError, match=words):
            hook.step()
        for kept, now in zip(before, ball.state(), strict=True):
            np.testing.assert_array_equal(kept, now)
        hook.close()
    hook = ball.launch([0, 0, RADIUS + 1e-6], UPRIGHT, [0, 0, -1.0], [0, 0, 0], mu=0.3, kappa=0)
    with pytest.raises(ValueError, match="resting contact"):
        hook.step()
    hook.close()


def test_flat_landing_and_other_forces_are_refused():
    """A box landing flat touches at four corners at once: refused. A force on the body
    (here xfrc_applied) is found after the engine's step, which is then undone."""
    needs("mujoco")
    mj, model, data = mujoco_box([0.05, 0.05, 0.05])
    data.qpos[2], data.qvel[2] = 0.0501, -1.0
    with E.MujocoHook(model, data, "box", mu=0.3, kappa=0.5) as hook:
        with pytest.raises(ValueError, match="4 points of the body touch the plane at once"):
            hook.step()
    mj.mj_resetData(model, data)
    data.qvel[2] = -1.0
    data.xfrc_applied[1, 0] = 1.0
    qpos, qvel = data.qpos.copy(), data.qvel.copy()
    with E.MujocoHook(model, data, "box", mu=0.3, kappa=0.5) as hook:
        with pytest.raises(
            ValueError, match="force other than gravity.*as it was before this step"
        ):
            hook.step()
    np.testing.assert_array_equal(data.qpos, qpos)
    np.testing.assert_array_equal(data.qvel, qvel)
    assert data.time == 0.0
    import mujoco

    two = mujoco.MjModel.from_xml_string(
        '<mujoco><worldbody><geom type="plane" size="0 0 1"/>'
        '<body name="ball" pos="0 0 1"><freejoint/><geom type="sphere" size="0.1"/></body>'
        '<body pos="0 0 1.19"><freejoint/><geom type="sphere" size="0.1"/></body>'
        "</worldbody></mujoco>"
    )  # two balls overlapping by 1 cm
    with E.MujocoHook(two, mujoco.MjData(two), "ball", mu=0.3, kappa=0.5) as hook:
        with pytest.raises(ValueError, match="constraint force .a contact with another body"):
            hook.step()


def test_close_gives_the_contact_back_and_moving_the_body_resyncs():
    needs("mujoco")
    import mujoco

    xml = (
        '<mujoco><worldbody><geom name="floor" type="plane" size="0 0 1"/>'
        '<body name="ball" pos="0 0 1"><freejoint/><geom type="sphere" size="0.1"/></body>'
        '<body name="cube" pos="1 0 1"><freejoint/><geom type="box" size="0.1 0.1 0.1"/>'
        "</body></worldbody></mujoco>"
    )
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    bits = model.geom_contype.copy(), model.geom_conaffinity.copy()
    hook = E.MujocoHook(model, data, "ball", mu=0.3, kappa=0.5)

    def collide(a, b):
        ct, ca = model.geom_contype, model.geom_conaffinity
        return bool(ct[a] & ca[b] or ct[b] & ca[a])

    assert not collide(0, 1) and collide(0, 2) and collide(1, 2)  # floor-ball off only
    for _ in range(3):
        hook.step()
    assert hook.position[2] > data.qpos[2]  # the exact flight is above the engine's
    data.qpos[2] = 0.5  # the user moves the ball: the hook starts again from there
    np.testing.assert_array_equal(hook.position, data.qpos[:3])
    hook.close()
    np.testing.assert_array_equal(model.geom_contype, bits[0])
    np.testing.assert_array_equal(model.geom_conaffinity, bits[1])
    with pytest.raises(RuntimeError, match="closed"):
        hook.step()


def test_a_tangential_law_is_applied_to_a_ball():
    needs("mujoco")
    world = SCENES["mujoco"]()
    law = Walton(beta0=0.4)
    hook = world.launch([0, 0, 0.3], UPRIGHT, [2.0, 0.0, -1.0], [0, 30.0, 0], mu=0.3,
                        kappa=0.6, tangential=law)  # fmt: skip
    out = hook.step()
    while not out.impacted:
        out = hook.step()
    hit = out.impacts[0]
    # the reference from the launch alone: the parabola to the floor, then the law
    x0, v0, w0 = np.array([0, 0, 0.3]), np.array([2.0, 0.0, -1.0]), np.array([0, 30.0, 0])
    tc = (v0[2] + np.sqrt(v0[2] ** 2 + 2 * G * (x0[2] - RADIUS))) / G
    exact = solve_sphere(BALL, v0 + DOWN * tc, w0, mu=0.3, kappa=0.6, surface=FLOOR,
                         tangential=law)  # fmt: skip
    assert abs(hit.time - tc) < 1e-12
    np.testing.assert_allclose(hit.velocity_after, exact.after.velocity, rtol=0, atol=1e-12)
    np.testing.assert_allclose(hit.spin_after, exact.after.spin, rtol=0, atol=1e-10)
    assert exact.regime != "slip"  # the law's stick branch, where Walton differs from rigid
    assert type(hit.exact).__name__ == "CompliantSphereImpact"
    _, model, data = mujoco_box([0.05, 0.05, 0.05])
    with pytest.raises(ValueError, match="tangential applies to a sphere"):
        E.MujocoHook(model, data, "box", mu=0.3, kappa=0.5, tangential=law)


@pytest.mark.parametrize(
    "change, error, message",
    [
        ({"mu": -0.1}, ValueError, "mu must be >= 0"),
        ({"mu": "0.3"}, TypeError, "mu"),
        ({"kappa": 1.5}, ValueError, r"kappa must be in \[0, 1\]"),
        ({"kappa": [0.5, 0.6]}, ValueError, "kappa must be a single number"),
        (
            {"law": "hertz"},
            ValueError,
            "law must be one of poisson, newton, energetic; got 'hertz'",
        ),
        ({"law": 3}, TypeError, "law must be one of"),
        ({"tangential": "walton"}, TypeError, "tangential must be a tangential compliance law"),
        ({"rest_speed": -1.0}, ValueError, "rest_speed must be None or a finite speed >= 0"),
        ({"rest_speed": "fast"}, TypeError, "rest_speed must be None or a finite speed"),
        ({"body": "nothing"}, ValueError, "body must name a body of the model, got 'nothing'"),
        ({"body": 2.0}, TypeError, "body must be a body name or id, got 2.0"),
        ({"body": 0}, ValueError, "body must have one free joint"),
        ({"plane": 1}, ValueError, "plane must be a plane geom, got 1"),
        ({"plane": 9}, ValueError, r"plane must be a plane id in \[0, 2\), got 9"),
        ({"model": None}, TypeError, "model must be a mujoco.MjModel, got NoneType"),
        ({"data": "d"}, TypeError, "data must be a mujoco.MjData, got str"),
    ],
)
def test_bad_mujoco_input_is_named(change, error, message):
    needs("mujoco")
    model, data = mujoco_ball()
    args = {"model": model, "data": data, "body": "ball", "mu": 0.3, "kappa": 0.5, **change}
    with pytest.raises(error, match=message):
        E.MujocoHook(args.pop("model"), args.pop("data"), args.pop("body"), **args)


def test_mujoco_shapes_and_pairs_the_hook_cannot_take():
    needs("mujoco")
    import mujoco

    def model(body, contact=""):
        xml = (
            '<mujoco><worldbody><geom name="floor" type="plane" size="0 0 1"/>'
            f'<geom name="wall" type="plane" size="0 0 1" zaxis="1 0 0"/>{body}'
            f"</worldbody>{contact}</mujoco>"
        )
        m = mujoco.MjModel.from_xml_string(xml)
        return m, mujoco.MjData(m)

    ball = '<body name="b" pos="0 0 1"><freejoint/><geom name="g" type="sphere" size="0.1"/></body>'
    m, d = model(ball)
    with pytest.raises(ValueError, match="plane must be given: the model has 2 plane geoms"):
        E.MujocoHook(m, d, "b", mu=0.3, kappa=0.5)
    m, d = model(ball, '<contact><pair geom1="floor" geom2="g"/></contact>')
    with pytest.raises(ValueError, match="explicit contact <pair>"):
        E.MujocoHook(m, d, "b", mu=0.3, kappa=0.5, plane="floor")
    m, d = model('<body name="b"><freejoint/><geom type="ellipsoid" size="0.1 0.2 0.3"/></body>')
    with pytest.raises(ValueError, match="sphere, capsule and box geoms.*ELLIPSOID"):
        E.MujocoHook(m, d, "b", mu=0.3, kappa=0.5, plane="floor")
    m, d = model('<body name="b"><freejoint/><geom type="sphere" size="0.1" pos="0.1 0 0"/>'
                 '<geom type="sphere" size="0.1" pos="0 0 0" mass="0"/></body>')  # fmt: skip
    with pytest.raises(ValueError, match="centre of mass at its frame's origin"):
        E.MujocoHook(m, d, "b", mu=0.3, kappa=0.5, plane="floor")


def test_bad_pybullet_input_is_named():
    needs("pybullet")
    world = SCENES["pybullet"]()
    try:
        with pytest.raises(TypeError, match="body must be a PyBullet body id"):
            E.PybulletHook(1.5, world.plane, mu=0.3, kappa=0.5, client=world.client)
        with pytest.raises(ValueError, match="body must be a body of client"):
            E.PybulletHook(99, world.plane, mu=0.3, kappa=0.5, client=world.client)
        with pytest.raises(
            ValueError, match="body must have a sphere or box shape, got GEOM_PLANE"
        ):
            E.PybulletHook(world.plane, world.body, mu=0.3, kappa=0.5, client=world.client)
        shape = world.pb.createCollisionShape(world.pb.GEOM_SPHERE, radius=0.1, **world.kw)
        other = world.pb.createMultiBody(1.0, shape, basePosition=[5, 0, 1], **world.kw)
        with pytest.raises(ValueError, match="plane must be a body whose one collision shape"):
            E.PybulletHook(world.body, other, mu=0.3, kappa=0.5, client=world.client)
        with pytest.raises(ValueError, match="client must be a connected PyBullet client"):
            E.PybulletHook(world.body, world.plane, mu=0.3, kappa=0.5, client=world.client + 7)
        with pytest.raises(ValueError, match="mu must be >= 0"):
            E.PybulletHook(world.body, world.plane, mu=-1, kappa=0.5, client=world.client)
        pb, kw = world.pb, world.kw
        pb.changeDynamics(world.body, -1, linearDamping=0.04, **kw)  # Bullet's default
        hook = world.launch([0, 0, 1.0], UPRIGHT, [0, 0, -1.0], [0, 0, 0], mu=0.3, kappa=0.5)
        with pytest.raises(ValueError, match="velocity changed by more than gravity"):
            hook.step()
    finally:
        world.close()


def test_capsule_end_impact_is_the_rigid_law():
    """A tumbling capsule lands on one of its round ends: the contact point lies a radius
    below that end's centre, on the plane, and the impact is solve_rigid's there."""
    needs("mujoco")
    import mujoco
    from scipy.spatial.transform import Rotation

    model = mujoco.MjModel.from_xml_string(
        f'<mujoco><option gravity="0 0 {-G}"/><worldbody><geom type="plane" size="0 0 1"/>'
        '<body name="pill" pos="0 0 0.5"><freejoint/>'
        '<geom type="capsule" size="0.02 0.06" mass="0.3"/></body></worldbody></mujoco>'
    )
    data = mujoco.MjData(model)
    rng = np.random.default_rng(4)
    for _ in range(4):
        mujoco.mj_resetData(model, data)
        data.qpos[3:] = Rotation.random(random_state=rng).as_quat(scalar_first=True)
        data.qvel[:] = rng.uniform(-8, 8, 6)
        data.qvel[2] = -1.5
        with E.MujocoHook(model, data, "pill", mu=0.5, kappa=0.6) as hook:
            out = hook.step()
            while not out.impacted:
                out = hook.step()
        hit = out.impacts[0]
        turn = rotation(hit.orientation)
        axis = turn[:, 2]
        ends = [hit.position + s * 0.06 * axis for s in (-1, 1)]
        lower = min(ends, key=lambda e: e[2])
        np.testing.assert_allclose(hit.point, lower - [0, 0, 0.02], rtol=0, atol=1e-12)
        inertia = turn @ np.diag(model.body_inertia[1]) @ turn.T
        body = RigidBody(0.3, inertia, hit.point - hit.position)
        exact = solve_rigid(body, hit.velocity_before, hit.spin_before, mu=0.5, kappa=0.6,
                            surface=FLOOR)  # fmt: skip
        speed = np.linalg.norm(hit.velocity_before) + 0.08 * np.linalg.norm(hit.spin_before)
        assert np.max(np.abs(exact.velocity - hit.velocity_after)) <= 1e-12 * speed
        assert 0.08 * np.max(np.abs(exact.spin - hit.spin_after)) <= 1e-12 * speed


@pytest.mark.parametrize("integrator", ["Euler", "RK4", "implicit", "implicitfast"])
def test_every_mujoco_integrator(integrator):
    """Under constant gravity every MuJoCo integrator gives the exact velocity at the steps,
    so the bounce is exact under each; RK4's positions are exact too (no drift), the others
    lag by g h^2 / 2 a step."""
    needs("mujoco")
    import mujoco

    scene = SCENES["mujoco"]()
    scene.model.opt.integrator = getattr(mujoco.mjtIntegrator, f"mjINT_{integrator.upper()}")
    h = scene.timestep
    cases = random_launches(10, seed=7)
    cases[0][:, 2] += RADIUS
    for launch in zip(*cases, strict=True):
        steps, hit, _, last, _ = through_impact(scene, launch, after=5)
        x, _, v, w, mu, kappa = launch
        v_ref, w_ref, x_ref, _, speed = ball_reference(x, v, w, mu, kappa, steps * h)
        position, velocity, spin = scene.state()
        assert np.max(np.abs(velocity - v_ref)) <= 1e-9 * speed
        assert RADIUS * np.max(np.abs(spin - w_ref)) <= 1e-9 * speed
        lag = 0.0 if integrator == "RK4" else -0.5 * G * h * h * (steps - hit)
        np.testing.assert_allclose(position - x_ref, [0, 0, lag], rtol=0, atol=1e-12)


def test_one_hook_a_model_and_a_dropped_hook_gives_the_contact_back():
    needs("mujoco")
    import gc

    model, data = mujoco_ball()
    bits = model.geom_contype.copy(), model.geom_conaffinity.copy()
    hook = E.MujocoHook(model, data, "ball", mu=0.3, kappa=0.5)
    with pytest.raises(ValueError, match="already has an open hook"):
        E.MujocoHook(model, data, "ball", mu=0.3, kappa=0.5)
    assert not np.array_equal(model.geom_contype, bits[0])  # the open hook's bits kept
    del hook  # dropped without close(): the engine gets its contact back all the same
    gc.collect()
    np.testing.assert_array_equal(model.geom_contype, bits[0])
    np.testing.assert_array_equal(model.geom_conaffinity, bits[1])
    with E.MujocoHook(model, data, "ball", mu=0.3, kappa=0.5) as again:  # a new one opens
        again.step()
    np.testing.assert_array_equal(model.geom_contype, bits[0])


def test_one_hook_a_pybullet_client():
    needs("pybullet")
    world = SCENES["pybullet"]()
    try:
        hook = world.launch([0, 0, 1.0], UPRIGHT, [0, 0, -1.0], [0, 0, 0], mu=0.3, kappa=0.5)
        with pytest.raises(ValueError, match="already has an open hook"):
            world.launch([0, 0, 1.0], UPRIGHT, [0, 0, -1.0], [0, 0, 0], mu=0.3, kappa=0.5)
        pb, kw = world.pb, world.kw
        shape = pb.getCollisionShapeData(world.body, -1, **kw)[0][3][0]  # the ball's radius
        pb.resetBasePositionAndOrientation(world.body, [0, 0, 0.5 * shape], [0, 0, 0, 1], **kw)
        pb.performCollisionDetection(**kw)  # sunk into the plane: no contact while hooked
        assert not pb.getContactPoints(world.body, world.plane, **kw)
        hook.close()
        pb.performCollisionDetection(**kw)
        assert pb.getContactPoints(world.body, world.plane, **kw)
        world.launch([0, 0, 1.0], UPRIGHT, [0, 0, -1.0], [0, 0, 0], mu=0.3, kappa=0.5).close()
    finally:
        world.close()
