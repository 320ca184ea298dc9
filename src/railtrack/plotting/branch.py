"""A branch of periodic solutions, drawn with its folds, its stability and the ring's ramps.

For any `railtrack.Branch` (from `railtrack.continuation`), after
`railtrack.check_branch` if its stability is wanted, and any
`railtrack.SpeedRamp` (from `railtrack.speed_ramp`).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ..solvers.solve import solve
from .style import BLACK, BLUE, MM, ORANGE, PURPLE, VERMILLION, new_figure

__all__ = ["plot_branch", "plot_multipliers", "ramp_on_branch"]


def ramp_on_branch(ramp, branch, samples: int = 4096) -> list[tuple[int, float] | None]:
    """For each speed of a ramp, the branch point its steady state lies on.

    The branch's crossings of each speed are polished by `railtrack.solve`
    (`Branch.solutions_at` as starting points), and the ring's least sleeper
    displacement is compared with theirs.

    Returns, per speed, None where the ring found no periodic state, else
    (index of the branch point just before the nearest crossing, |min w of
    the ring - min w of that solution| [m]).
    """
    out = []
    track, train, foundation = branch.problem(0)
    for speed, low, periodic in zip(ramp.speeds, ramp.minimum, ramp.converged):
        if not periodic:
            out.append(None)
            continue
        before, _ = branch.crossings(float(speed))
        at = train.replace(speed=float(speed))
        dips = []
        for guess in branch.solutions_at(float(speed)):
            s = solve(track, at, foundation, harmonics=branch.harmonics, initial=guess,
                      stability="off")  # the branch says which are stable
            t = np.linspace(0.0, float(s.period), samples, endpoint=False)
            dips.append(float(s.sleeper_displacement(t).min()) if s.converged else np.nan)
        gaps = np.abs(np.array(dips) - low)
        k = int(np.nanargmin(gaps))
        out.append((int(before[k]), float(gaps[k])))
    return out


def plot_branch(branch, *, linear: tuple | None = None, ramps: dict | None = None) -> Figure:
    """-min w [mm] along a speed branch, its folds marked, optionally the linear law's curve.

    Where ``branch.stable`` is set (`railtrack.check_branch`), stable parts
    are drawn solid, unstable parts dotted, parts whose verdict is unknown
    grey and dashed, and the points the ring was run on are marked.

    Parameters
    ----------
    branch : Branch
        From ``continuation(..., parameter="speed")``.
    linear : (speeds, lowest), optional
        The linear law's min w [m] over speeds [m/s] for comparison.
    ramps : dict, optional
        Label -> `railtrack.SpeedRamp`: the ring's steady dips along rising or
        falling speeds, joined in the order run, each ramp in its own colour,
        line style and marker (the first, ▶, for a rising ramp, the second,
        ◀, for a falling one); a cross (x for the first, + for the second)
        where the response did not repeat (its dip over the last period run).

    Folds are black diamonds; the linear law is grey and dashed.
    """
    fig, ax = new_figure()
    dip = -branch.minimum_displacement() * MM
    if branch.stable is None:
        ax.plot(branch.values, dip, "-", color=BLUE, lw=1.5, label="cubic law, continued branch",
                gid="branch")
    else:
        by_hill = getattr(branch, "multipliers", None) is not None
        judge = "Floquet" if by_hill else "ring"
        verdicts = _verdicts(branch.stable)
        for verdict, style, colour in (("stable", "-", BLUE), ("unstable", ":", BLUE),
                                       ("unknown", "--", "0.6")):
            drawn = verdicts == verdict
            if verdict == "unknown" and not drawn.any():
                continue   # no legend entry for what is not there
            drawn[1:] |= drawn[:-1].copy()   # one point on, so that the pieces meet
            shown = np.where(drawn, dip, np.nan)
            label = f"branch, {verdict} ({judge})" if verdict != "unknown" else \
                "branch, stability unknown (the search could miss a multiplier)"
            ax.plot(branch.values, shown, style, color=colour, lw=1.5, label=label,
                    gid=f"branch-{verdict}")
        if by_hill:
            tori = [c for c in branch.changes if c.kind != "fold"]
            at = [np.interp(c.value, branch.values[c.index:c.index + 2],
                            dip[c.index:c.index + 2]) for c in tori]
            ax.plot([c.value for c in tori], at, "s", mfc="none", color=VERMILLION, ms=6,
                    label="stability changes away from folds", gid="changes")
        else:
            checked = np.array(sorted(branch.checks))
            ax.plot(branch.values[checked], dip[checked], "o", mfc="none", color=BLUE, ms=5,
                    label="checked by the ring", gid="checked")
    indices = [fold.index for fold in branch.folds]
    ax.plot(branch.values[indices], dip[indices], "D", color=BLACK, ms=5, label="folds",
            gid="folds", zorder=4)
    for n, i in enumerate(indices, 1):
        ax.annotate(f"{n}: {branch.values[i]:.1f}", (branch.values[i], dip[i]), fontsize=7,
                    xytext=(4, 4 if n % 2 else -10), textcoords="offset points")
    if linear is not None:
        ax.plot(linear[0], -np.asarray(linear[1]) * MM, "--", color="0.4",
                label="linear law (same k2, η2)", gid="linear")
    for n, (label, ramp) in enumerate((ramps or {}).items()):
        colour, marker, cross, style = _RAMP_STYLES[n % len(_RAMP_STYLES)]
        ramp_dip, periodic = -ramp.minimum * MM, np.asarray(ramp.converged, bool)
        ax.plot(ramp.speeds, ramp_dip, ls=style, color=colour, lw=0.9, marker=marker, ms=5,
                markevery=list(periodic), label=label, gid=f"ramp-{n}")
        if not periodic.all():
            ax.plot(ramp.speeds[~periodic], ramp_dip[~periodic], cross, color=colour, ms=7,
                    mew=1.5, label=f"{label}: no periodic state (last period)",
                    gid=f"ramp-{n}-aperiodic")
    ax.set_xlabel("train speed v [m/s]")
    ax.set_ylabel("largest sleeper dip −min w [mm]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def _verdicts(stable) -> np.ndarray:
    """"stable", "unstable" or "unknown" per point from ``Branch.stable`` (True, False, None)."""
    return np.array([{True: "stable", False: "unstable"}.get(flag, "unknown") for flag in stable])


def plot_multipliers(branch, *, scanned=None, xlim=None) -> Figure:
    """The dominant Floquet multiplier |mu| along a branch, against the unit circle.

    Parameters
    ----------
    branch : Branch
        After `railtrack.check_branch` with Hill's method (``branch.multipliers`` set).
    scanned : array_like, optional
        |mu| of the most unstable disturbance of any wavelength at each point
        (`railtrack.floquet` with ``theta="scan"``), drawn dashed.
    xlim : (float, float), optional
        Speed range shown [m/s]; set here, not afterwards, so that the
        labels of the changes are placed for the range the reader sees.

    Points whose verdict is unknown (`railtrack.Branch.verdicts`) are left
    out.  Each part between folds is drawn in turn from the branch's start; folds
    are black diamonds, the other changes of stability open squares labelled
    with their kind.
    """
    if getattr(branch, "multipliers", None) is None:
        raise ValueError("the branch has no multipliers: run rt.check_branch(branch) first")
    fig, ax = new_figure()
    # where the verdict is unknown the search could have missed the dominant multiplier:
    # the largest one it found is no value to draw
    size = np.where(_verdicts(branch.stable) == "unknown", np.nan, np.abs(branch.multipliers))
    ax.semilogy(branch.values, size, "-", color=BLUE, lw=1.3,
                label="dominant |μ|, disturbances that repeat every wagon", gid="multiplier")
    if scanned is not None:
        ax.semilogy(branch.values, np.asarray(scanned), "--", color=ORANGE, lw=1.1,
                    label="dominant |μ|, disturbances of any wavelength", gid="scanned")
    ax.axhline(1.0, color=BLACK, lw=0.8, gid="unit-circle")
    names = {"real +": "real, +1", "real -": "real, −1", "complex": "complex pair"}
    labelled, notes = set(), []
    for change in branch.changes:
        # every change sits on the unit circle, by definition; the points either
        # side are a step of the branch away
        fold = change.kind == "fold"
        label = "folds (a real multiplier through +1)" if fold else \
            "changes away from folds"
        ax.plot(change.value, 1.0, "D" if fold else "s", color=BLACK if fold else VERMILLION,
                mfc=BLACK if fold else "none", ms=5, gid="change",
                label=None if label in labelled else label)
        labelled.add(label)
        if not fold:
            notes.append(ax.annotate(
                f"{names[change.kind]}, {change.value:.1f} m/s", (change.value, 1.0),
                fontsize=7, xytext=(4, -12 if change.gains else 6),
                textcoords="offset points", gid="change-label"))
    if xlim is not None:
        ax.set_xlim(*xlim)
    _separate_labels(ax, notes)
    ax.set_xlabel("train speed v [m/s]")
    ax.set_ylabel("largest Floquet multiplier |μ| per period [-]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def _separate_labels(ax, notes, step: float = 9.0, tries: int = 8) -> None:
    """Move each label away from the unit circle, a line at a time, until it overlaps none before it.

    Two changes a few m/s apart on the same side of the line (a pair that comes
    in at 513.3 and another at 537.9 m/s) would otherwise print over each other.
    """
    # lay the figure out first: constrained layout moves the axes, and the labels with them
    ax.figure.draw_without_rendering()
    renderer = ax.figure.canvas.get_renderer()
    placed = []
    for note in sorted(notes, key=lambda n: n.xy[0]):
        dx, dy = note.xyann
        away = step if dy > 0 else -step
        for _ in range(tries):
            box = note.get_window_extent(renderer)
            if not any(box.overlaps(other) for other in placed):
                break
            dy += away
            note.xyann = (dx, dy)
        placed.append(note.get_window_extent(renderer))


_RAMP_STYLES = ((ORANGE, ">", "x", "-"), (PURPLE, "<", "+", "--"),
                (VERMILLION, "^", "1", "-."), (BLACK, "v", "2", (0, (6, 2))))
"""Colour, marker of a periodic state, marker of an aperiodic one and line style of each ramp:
a rising ramp (the first) points right, a falling one left."""
