"""A classroom explorer: sliders for the train and the track, three live panels.

`explorer_state` solves one slider setting, `explorer_figure` draws it (no widgets needed, so
the book shows it as a still), and `explore` wires both to ipywidgets sliders in JupyterLab.
"""

from __future__ import annotations

import base64
import inspect
import io
import textwrap
from typing import TYPE_CHECKING, Any, NamedTuple

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from ..model.foundations import BilinearFoundation, CubicFoundation, LinearFoundation
from .style import VERMILLION, new_figure
from .solution import PANEL_LABELS, draw_solution
from ..solvers.solution import ConvergenceError, Solution
from ..solvers.solve import solve
from ..model.track import Track
from ..model.train import Train

if TYPE_CHECKING:
    import ipywidgets

__all__ = ["DEFAULTS", "ExplorerState", "case_inputs", "solve_case", "explorer_state",
           "explorer_figure", "explore"]

LAWS = {"linear": "linear, eq. (22)", "bilinear": "bilinear, eq. (24)", "cubic": "cubic, eq. (25)"}
TRAINS = {"paper": "paper's wagon", "passenger_coach": "passenger coach", "freight_wagon": "freight wagon"}
WORST_TRUNCATION = 1e-2  # a solution whose estimated truncation error exceeds this is not drawn
# The controls from top to bottom: a dropdown's choices, or a slider's (label, min, max, step)
CONTROLS = {"train": TRAINS, "speed": ("speed v [m/s]", 5.0, 700.0, 1.0),
            "pad_damping": ("pad damping η₁ [kN s/m]", 0.0, 2000.0, 10.0),
            "foundation_stiffness": ("foundation stiffness k₂ [MN/m]", 1.0, 100.0, 1.0),
            "foundation_damping": ("foundation damping η₂ [kN s/m]", 0.0, 1000.0, 10.0),
            "law": LAWS, "ratio": ("tension ratio e = k₂⁻/k₂⁺ [-]", 0.0, 1.0, 0.05),
            "epsilon": ("cubic term ε [-]", 0.0, 2.0, 0.05)}
LABELS = PANEL_LABELS


class ExplorerState(NamedTuple):
    """One setting of the explorer and what came of it.

    Attributes
    ----------
    values : dict or None
        The slider values in the units of `DEFAULTS`; None for a Solution solved elsewhere.
    solution : Solution or None
        The solved case; None if the input was refused.
    error : str or None
        Why nothing is drawn (bad input, no convergence, too few harmonics), else None.
    """

    values: dict | None
    solution: Solution | None
    error: str | None

    @property
    def title(self) -> str:
        """The figure's title: the case, then m and the truncation estimate, or the error."""
        v, s = self.values, self.solution
        if v is None:  # a bare Solution
            case = (f"{float(s.train.wagon_length):g} m wagon, {float(s.train.speed):g} m/s, "
                    f"{type(s.foundation).__name__}")
        else:
            law = {"bilinear": f"bilinear e = {v['ratio']:g}",
                   "cubic": f"cubic ε = {v['epsilon']:g}"}.get(v["law"], str(v["law"]))
            case = (f"{TRAINS.get(v['train'], v['train'])}, {v['speed']:g} m/s, {law} law, "
                    f"k₂ = {v['foundation_stiffness']:g} MN/m, η₁ = {v['pad_damping']:g}, "
                    f"η₂ = {v['foundation_damping']:g} kN s/m")
        if self.error is not None:
            return case + "\n" + textwrap.fill(f"NOT DRAWN: {self.error}", 110)
        return f"{case}\nm = {s.harmonics} harmonics, truncation error ≈ {s.truncation_error:.0e}"


def case_inputs(speed: float = 45.0, pad_damping: float = 1000.0,
                foundation_damping: float = 200.0, foundation_stiffness: float = 20.0,
                law: str = "linear", ratio: float = 0.5, epsilon: float = 0.8,
                train: str = "paper") -> tuple[Track, Train, Any]:
    """The track, train and foundation law (SI) of one slider setting.

    Parameters
    ----------
    speed : float
        Train speed v [m/s].
    pad_damping, foundation_damping : float
        eta1 and eta2 [kN s/m] (the paper: 1000 and 200).
    foundation_stiffness : float
        k2, for the bilinear law k2+ in compression [MN/m] (the paper: 20).
    law : {"linear", "bilinear", "cubic"}
        Eq. (22), eq. (24) with k2- = e k2+, or eq. (25) with the paper's k3 = 2e13 N/m^3.
    ratio, epsilon : float
        e = k2- / k2+ of the bilinear law (0: tensionless) and eps of the cubic law [-].
    train : {"paper", "passenger_coach", "freight_wagon"}
        `Train.paper`, `Train.passenger_coach` or `Train.freight_wagon` at `speed`.

    Returns
    -------
    (Track, Train, foundation)
        ``Track.paper()`` with eta1 replaced, the train and the law.  Raises
        ValueError for an unknown law or train or values the library refuses.
    """
    if law not in LAWS or train not in TRAINS:
        raise ValueError(f"law must be in {list(LAWS)}, train in {list(TRAINS)}; got {law!r}, {train!r}")
    k2, eta2 = foundation_stiffness * 1e6, foundation_damping * 1e3  # SI: N/m, N s/m
    k3 = CubicFoundation.paper().cubic_stiffness  # Section 4.3: 2e13 N/m^3
    foundation = {"linear": lambda: LinearFoundation(k2, eta2),
                  "bilinear": lambda: BilinearFoundation(k2, ratio * k2, eta2),
                  "cubic": lambda: CubicFoundation(k2, k3, epsilon, eta2)}[law]()
    return Track.paper(pad_damping=pad_damping * 1e3), getattr(Train, train)(speed=speed), foundation


DEFAULTS: dict[str, Any] = {k: p.default for k, p in inspect.signature(case_inputs).parameters.items()}
"""The paper's case (Table 1, Section 4) in slider units: m/s, kN s/m, MN/m."""


def solve_case(**values) -> Solution:
    """`railtrack.solve` (Newton, ``harmonics="auto"``) of the case `case_inputs` builds.

    Takes the keywords of `case_inputs` (slider units); raises like it and like `solve`.
    """
    return solve(*case_inputs(**values), harmonics="auto")


def explorer_state(**values) -> ExplorerState:
    """Solve one slider setting without raising: errors go into `ExplorerState.error`.

    Takes the keywords of `case_inputs` (slider units; missing ones from
    `DEFAULTS`).  ``error`` is set when the input is refused, the solve did
    not converge, or its estimated truncation error exceeds 1 %.
    """
    values = {**DEFAULTS, **values}
    try:
        solution = solve_case(**values)
    except (ValueError, TypeError, ArithmeticError, np.linalg.LinAlgError, ConvergenceError) as exc:
        return ExplorerState(values, None, f"{type(exc).__name__}: {exc}")
    return ExplorerState(values, solution, _doubt(solution))


def _doubt(solution: Solution) -> str | None:
    """Why `solution` should not be drawn (not converged, truncation error > 1 %), else None."""
    if not solution.converged:
        return f"not converged: {solution.message}"
    if not solution.truncation_error <= WORST_TRUNCATION:
        return f"estimated truncation error {solution.truncation_error:.1e} > 1 %"
    return None


def explorer_figure(state: ExplorerState | Solution, samples: int = 600) -> Figure:
    """Three panels of one case: sleeper displacement, rail-seat load, deflection bowl.

    Parameters
    ----------
    state : ExplorerState or Solution
        What to draw.  A state with an error gets empty, labelled panels and
        the error in the title, never a wrong curve.
    samples : int
        Instants over one period T = H / v.

    Returns
    -------
    matplotlib.figure.Figure
        Sleeper displacement w [mm] and rail-seat load [kN] (compression > 0)
        against t [ms] over one period; rail and sleepers [mm] along x [m] at t = 0.
    """
    state = ExplorerState(None, state, _doubt(state)) if isinstance(state, Solution) else state
    fig, axes = new_figure(3, 1, height=2.3)
    fig.suptitle(state.title, fontsize="small", color=VERMILLION if state.error else "black")
    if not state.error:
        draw_solution(axes, state.solution, samples)
    for ax, xlabel, ylabel in zip(axes, LABELS[::2], LABELS[1::2]):
        ax.set(xlabel=xlabel, ylabel=ylabel)
        ax.grid(True, alpha=0.3)
    return fig


def _png_output(state: ExplorerState) -> dict:
    """The explorer figure of `state` as one Jupyter display_data output (PNG, title as text)."""
    fig = explorer_figure(state)
    fig.savefig(buffer := io.BytesIO(), format="png", dpi=90)
    plt.close(fig)
    return {"output_type": "display_data", "metadata": {}, "data": {
        "image/png": base64.b64encode(buffer.getvalue()).decode("ascii"), "text/plain": state.title}}


def _slider_value(name: str, value: Any) -> float:
    """`value` as a float for the slider `name`; ValueError unless a finite real number."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.number)) \
            or not np.isfinite(value):
        raise ValueError(f"{name} must be a finite number in the units of its slider "
                         f"({CONTROLS[name][0]}); got {value!r}")
    return float(value)


def explore(**initial) -> ipywidgets.VBox:
    """Sliders for speed, dampings, foundation stiffness, law, e, ε and train; live panels.

    `initial` takes the keywords of `case_inputs` (slider units: m/s, kN s/m,
    MN/m).  Returns an ipywidgets.VBox: the controls above an ``Output`` that
    shows `explorer_figure`, with attributes ``controls`` (name -> widget),
    ``output`` and ``state`` (the `ExplorerState` drawn last).  Sliders have
    ``continuous_update=False``: one solve per release, not one per pixel dragged.
    A setting outside a slider's range (e.g. ``speed=900``) widens that slider
    to it rather than being clamped; one that is not a finite number raises
    ValueError.
    """
    try:
        import ipywidgets as widgets
    except ImportError as exc:
        raise ImportError("railtrack's explorer needs ipywidgets (and JupyterLab to show it): "
                          "pip install ipywidgets") from exc
    if set(initial) - set(DEFAULTS):
        raise TypeError(f"explore() got unknown settings {sorted(set(initial) - set(DEFAULTS))}")
    values, wide = {**DEFAULTS, **initial}, {"description_width": "16em"}
    controls = {}
    for name, spec in CONTROLS.items():
        if isinstance(spec, dict):
            controls[name] = widgets.Dropdown(options=[(text, key) for key, text in spec.items()],
                                              value=values[name], description=name, style=wide)
        else:
            value = _slider_value(name, values[name])
            # A slider clamps a value outside [min, max] without a word: widen it instead,
            # so that the case drawn is the one asked for (solve refuses what is unphysical).
            controls[name] = widgets.FloatSlider(
                value=value, min=min(spec[1], value), max=max(spec[2], value), step=spec[3],
                description=spec[0], continuous_update=False, style=wide,
                layout=widgets.Layout(width="36em"))
    output = widgets.Output(layout=widgets.Layout(min_height="40em"))
    panel = widgets.VBox([*controls.values(), output])
    panel.controls, panel.output = controls, output

    def redraw(change=None) -> None:
        law = controls["law"].value
        controls["ratio"].disabled, controls["epsilon"].disabled = law != "bilinear", law != "cubic"
        current = {name: widget.value for name, widget in controls.items()}
        try:
            panel.state = explorer_state(**current)
            result = _png_output(panel.state)
        except Exception as exc:  # a callback must never raise: say what happened instead
            panel.state = ExplorerState(current, None, f"{type(exc).__name__}: {exc}")
            result = _png_output(panel.state)
        output.outputs = (result,)  # one assignment: the old figure stays until the new is ready

    for widget in controls.values():
        widget.observe(redraw, names="value")
    redraw()  # the first figure, and the disabled state of e and ε
    return panel
