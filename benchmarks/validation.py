"""Validation cases, one command: ``python -m benchmarks.validation CASE``.

* ``kharaz``: every model against Kharaz et al. (2001); prints the error table of
  ``docs/validation.md``, and writes its figures where ``--output DIR`` is given only
  (``make validation`` gives the git-ignored build/validation, ``make validation
  VALIDATION=docs/images`` the published figures), so a plain run leaves them alone.
* ``chung-ooi --test N``: Chung & Ooi (2011) Test N (1-6), the benchmark's quantities
  beside the reference.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from . import chung_ooi, kharaz

#: The model drawn thick in the Kharaz figure.
BEST = "Mindlin-Deresiewicz (micro-slip), nu = 0.23"


def _available(models):
    """The models whose laws are importable (the impulse-space laws may be missing)."""
    out = []
    for label, model, material in models:
        try:
            model(np.array([30.0]), material)
        except ImportError as err:
            print(f"skipped {label}: {err}", file=sys.stderr)
            continue
        out.append((label, model, material))
    return out


def kharaz_figure(models, path: Path) -> None:
    """e_t, rebound spin and rebound angle over the incidence angle: measured points and
    every model's curve."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    data = kharaz.measured()
    measured = np.concatenate([a for a, _ in data.values()])
    low, high = float(measured.min()), float(measured.max())  # the digitization's range
    angles = np.linspace(low, high, 120)
    curves = [(label, model(angles, material)) for label, model, material in models]
    fig, axes = plt.subplots(1, 3, figsize=(15, 5.6), constrained_layout=True)
    titles = {"e_t": r"tangential restitution $e_t = v_x^+/v_x^-$",
              "spin": r"rebound spin $|\omega^+|$ (rad/s)",
              "rebound_angle": r"rebound angle of the centre (deg)"}  # fmt: skip
    styles = ["-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1)), (0, (1, 1)), (0, (8, 2))]
    for ax, key in zip(axes, titles, strict=True):
        for (label, values), style in zip(curves, styles, strict=False):
            if label == BEST:  # the model the page's conclusion is about
                ax.plot(angles, values[key], ls="-", lw=3.0, color="crimson", label=label)
            else:
                ax.plot(angles, values[key], ls=style, lw=1.4, label=label)
        ax.plot(*data[key], "ko", ms=6, label="measured (Kharaz et al. 2001)")
        ax.set_xlabel("incidence angle from the normal (deg)")
        ax.set_xlim(0.0, high + 2.0)
        ax.set_title(titles[key])
        ax.grid(alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncol=3, fontsize="small")
    fig.savefig(path, dpi=80)
    plt.close(fig)


def microslip_figure(path: Path, angles=(2.0, 4.0, 10.0, 20.0)) -> None:
    """One Kharaz impact in time at each of ``angles`` under micro-slip
    (:func:`spinimpact.viz.micro_slip.plot_micro_slip`): the friction force over Coulomb's
    bound, the stuck core's radius over the contact radius, the contact point's slip."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from spinimpact.model.compliance import MindlinDeresiewicz
    from spinimpact.viz.micro_slip import plot_micro_slip

    vx, vy = kharaz.incidence(np.array(angles))
    law = MindlinDeresiewicz(poisson_ratio=kharaz.OXIDE.poisson_ratio)
    fig = plot_micro_slip(law, kharaz.OXIDE.body, vx, vy, 0.0, mu=kharaz.MU,
                          kappa=kharaz.KAPPA, labels=[f"{a:g} deg" for a in angles])  # fmt: skip
    fig.savefig(path, dpi=80)
    plt.close(fig)


def mbf_figure(path: Path, poisson_ratio: float = 0.3, mu: float = 0.3) -> None:
    """Maw, Barber & Fawcett's normalized recoil angle against the normalized incidence
    angle, for a solid sphere with e = 1 (Chung & Ooi's Test 5 steel case)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from spinimpact import solve
    from spinimpact.core.compliance import maw_angles
    from spinimpact.core.tangential import mindlin_stiffness_ratio

    case = chung_ooi.TEST5[0]
    r = float(mindlin_stiffness_ratio(poisson_ratio))
    psi1 = np.linspace(0.1, 12.0, 90)  # r u-/(mu vn-)
    vn = case.normal_speed
    u0 = psi1 * mu * vn / r
    body = case.body()
    rows = {"rigid": solve(body, u0, -vn, 0.0, mu=mu, kappa=1.0)}
    try:
        from spinimpact.model.compliance import MindlinDeresiewicz, Stronge

        law = Stronge(poisson_ratio=poisson_ratio)
        rows["Stronge (impulse space)"] = solve(body, u0, -vn, 0.0, mu=mu, kappa=1.0,
                                                tangential=law)  # fmt: skip
        law = MindlinDeresiewicz(poisson_ratio=poisson_ratio)
        rows["Mindlin-Deresiewicz (micro-slip)"] = solve(body, u0, -vn, 0.0, mu=mu, kappa=1.0,
                                                         tangential=law)  # fmt: skip
    except ImportError as err:
        print(f"skipped Stronge: {err}", file=sys.stderr)

    def recoil(vx, vy, omega):  # Maw et al.'s psi_2 (core.compliance.maw_angles)
        vx, vy, omega = (np.asarray(x, dtype=float) for x in (vx, vy, omega))
        return maw_angles(u0, -vn, vx + body.radius * omega, vy, mu, poisson_ratio).recoil

    psi2 = {k: recoil(v.after.vx, v.after.vy, v.after.omega) for k, v in rows.items()}
    sims = [case.run(float(u), 0.0) for u in u0]
    psi2["Hertz-Mindlin in time"] = recoil(*([getattr(s.after, n) for s in sims]
                                             for n in ("vx", "vy", "omega")))  # fmt: skip
    fig, ax = plt.subplots(figsize=(7.5, 5.4), constrained_layout=True)
    for (label, values), style in zip(psi2.items(), ["--", "-.", ":", "-"], strict=False):
        ax.plot(psi1, values, ls=style, lw=1.8, label=label)
    ax.axhline(0, color="0.6", lw=0.8)
    ax.set_xlabel(r"normalized incidence angle $\Psi_1 = r\,u^-/(\mu v_n^-)$")
    ax.set_ylabel(r"normalized recoil angle $\Psi_2 = r\,u^+/(\mu v_n^+)$")
    ax.set_title(rf"solid sphere, $\nu$ = {poisson_ratio}, $r = 2(1-\nu)/(2-\nu)$ = {r:.3f},"
                 " e = 1", fontsize="medium")  # fmt: skip
    ax.legend(loc="upper left")
    ax.grid(alpha=0.3)
    fig.savefig(path, dpi=80)
    plt.close(fig)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks.validation")
    sub = parser.add_subparsers(dest="case", required=True)
    k = sub.add_parser("kharaz", help="every model against Kharaz et al. (2001)")
    k.add_argument(
        "--output",
        type=Path,
        default=None,
        help="directory to write the figures into (none written without it)",
    )
    c = sub.add_parser("chung-ooi", help="a Chung & Ooi (2011) benchmark test")
    c.add_argument("--test", type=int, required=True, choices=sorted(chung_ooi.TESTS))
    args = parser.parse_args(argv)
    if args.case == "chung-ooi":
        print(f"Chung & Ooi (2011), Test {args.test}")
        print("\n".join(chung_ooi.TESTS[args.test]()))
        return 0
    models = _available(kharaz.MODELS)
    print(kharaz.markdown_table([(label, kharaz.errors(m, mat)) for label, m, mat in models]))
    if args.output is None:
        return 0
    args.output.mkdir(parents=True, exist_ok=True)
    drawn = [m for m in models if m in kharaz.FIGURE_MODELS]
    kharaz_figure(drawn, args.output / "validation_kharaz.png")
    mbf_figure(args.output / "validation_mbf.png")
    microslip_figure(args.output / "validation_microslip.png")
    print(f"wrote {args.output / 'validation_kharaz.png'}, validation_mbf.png and "
          "validation_microslip.png")  # fmt: skip
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
