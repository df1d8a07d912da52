"""The module itself: its version and the names it shows."""

import re
from importlib import metadata

import eulerdyn
from conftest import REPO, run_cli


def crate_version() -> str:
    """The `version` of the eulerdyn crate: the first `version = "…"` of the repository's Cargo.toml, in its
    [package] table."""
    text = (REPO / "Cargo.toml").read_text()
    package = text.split("[package]", 1)[1].split("\n[", 1)[0]
    return re.search(r'^version\s*=\s*"([^"]+)"', package, re.MULTILINE).group(1)


def test_version_is_the_crates():
    assert isinstance(eulerdyn.__version__, str)
    assert eulerdyn.__version__ == crate_version()
    # What the command line says, and the version the wheel was installed as.
    assert run_cli("--version").stdout.split() == ["eulerdyn", eulerdyn.__version__]
    assert metadata.version("eulerdyn") == eulerdyn.__version__


def test_dir_shows_the_modules_names_only():
    names = dir(eulerdyn)
    public = {n for n in names if not n.startswith("_")}
    assert public == set(eulerdyn.__all__)
    assert public == {
        "RunError", "SceneError", "SceneLike", "Svg", "accuracy", "balance", "check", "compare", "events", "fit", "plot",
        "run", "score", "sweep", "view",
    }
    # What the implementation imports stays out of it (issue 27).
    for name in ("np", "pd", "os", "csv", "io", "math", "Dict", "Any", "Mapping", "Optional", "annotations"):
        assert name not in names, name
    assert "__version__" in names
    # `from eulerdyn import *` brings the same names.
    scope = {}
    exec("from eulerdyn import *", scope)
    assert set(scope) - {"__builtins__"} == public
