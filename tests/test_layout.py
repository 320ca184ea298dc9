"""The package's tree is its architecture (src/railtrack).

Each subpackage is a layer: a module may import from its own layer or from a
layer below, never from one above, and no two modules import each other,
directly or round a longer circle.  The import statements are read from the
source with `ast`, so the test sees lazy imports inside functions too.  The
public names of ``import railtrack as rt`` are listed here, so that a
reorganisation cannot drop one unnoticed.
"""

import ast
from pathlib import Path

import pytest

import railtrack as rt

PACKAGE = Path(rt.__file__).resolve().parent
LAYERS = ["model", "equations", "solvers", "timedomain", "studies", "plotting"]

PUBLIC = {
    "Track", "Train", "Passage", "LinearFoundation", "BilinearFoundation", "CubicFoundation",
    "CallableFoundation", "as_foundation", "solve", "METHODS", "sweep", "Sweep", "continuation",
    "Branch", "Fold", "check_stability", "StabilityCheck", "check_branch", "speed_ramp",
    "SpeedRamp", "Solution", "ConvergenceError", "ConvergenceWarning", "TruncationWarning",
    "analytic_coefficients",
    "sweep_speeds", "sweep_extremes", "rail_receptance", "rail_receptance_lattice_sum",
    "offset_receptance", "rail_coupling", "load_coefficients", "axle_factor",
    "simulate_time_domain", "TimeDomainSolution", "TimeStepWarning", "LongRunWarning",
    "NonFiniteLawError", "estimate_step_error", "explore", "dissipation", "Dissipation",
    "load_work", "floquet", "Floquet", "StabilityChange", "UnstableSolutionWarning",
    "ring_multipliers", "RingMultipliers", "SleeperCell", "GapFoundation", "CellSolution",
    "random_support", "RandomSupport", "Wheel", "CosineDip", "WheelSolution",
    "TimoshenkoRail", "p2_force", "EquivalentTrack", "equivalent_track",
    "PlausibilityWarning", "plausible_ranges", "plausibility",
}
PUBLIC |= {"RailSection", "UIC60", "UIC54", "DesignSummary", "eisenmann_factor"}   # issue 29
PUBLIC |= {"WinklerGround", "GroundSolution", "SoilLayer", "Ground", "LayeredGround"}  # issue 31
PUBLIC |= {"Vehicle"}   # issue 32: wheel=Vehicle in solve and simulate_time_domain


def _modules():
    return {".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts): path
            for path in PACKAGE.rglob("*.py")}


def _imports(name: str, path: Path) -> set[str]:
    """The railtrack modules that `name` imports (relative imports resolved)."""
    package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.startswith("railtrack"):
                found.add(target)
                found.update(f"{target}.{alias.name}" for alias in node.names)
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("railtrack"))
    return found


def _graph():
    modules = _modules()
    return {name: {m for m in _imports(name, path) if m in modules and m != name}
            for name, path in modules.items()}


def _layer(module: str) -> int | None:
    parts = module.split(".")
    return LAYERS.index(parts[1]) if len(parts) > 2 and parts[1] in LAYERS else None


def test_every_module_lives_in_a_layer():
    loose = [m for m in _modules() if m.count(".") == 1 and not m.endswith("__init__")]
    assert loose == [], "modules outside every subpackage"
    assert {p.name for p in PACKAGE.iterdir() if p.is_dir() and not p.name.startswith("_")} \
        == set(LAYERS)


def test_no_module_imports_from_a_layer_above_its_own():
    upward = [(m, t) for m, targets in _graph().items() for t in targets
              if _layer(m) is not None and _layer(t) is not None and _layer(t) > _layer(m)]
    assert upward == []


def test_no_import_circle():
    graph = {m: {t for t in ts if not t.endswith("__init__")} for m, ts in _graph().items()
             if not m.endswith("__init__")}
    state, circle = {}, []

    def visit(node, path):
        state[node] = "open"
        for nxt in graph.get(node, ()):
            if state.get(nxt) == "open":
                circle.append(path + [nxt])
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = "done"

    for node in graph:
        if node not in state:
            visit(node, [node])
    assert circle == []


def test_each_subpackage_says_what_it_holds_and_may_import():
    for layer in LAYERS:
        doc = ast.get_docstring(ast.parse((PACKAGE / layer / "__init__.py").read_text()))
        assert doc and "import" in doc.lower(), layer


@pytest.mark.parametrize("name", sorted(PUBLIC))
def test_the_public_names_stay(name):
    assert name in rt.__all__ and hasattr(rt, name)
