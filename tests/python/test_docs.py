"""The docs say what the module is: every name docs/guide.md documents for `import polyroll` exists
and runs, its quoted error messages are the module's, and every ```python snippet in docs/ runs as
written. The snippets' runs are shortened through the documented `time_limit` keyword (a run's
simulated time), so the test takes seconds; nothing else in them changes."""
import builtins
import glob
import inspect
import os
import re

import pytest

import polyroll

SOURCE = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
GUIDE = os.path.join(SOURCE, "docs", "guide.md")

# Simulated seconds a snippet's run, simulation or sweep point is given unless it says otherwise.
SHORT_S = 0.3

# Backticked words of the guide's Python section that are not the module's names: a program, an
# environment variable, JSON's null and a standard module. (Python's builtins are skipped too.)
NOT_THE_MODULES = {"python3", "PYTHONPATH", "null", "sysconfig"}


def python_section():
    with open(GUIDE, encoding="utf-8") as f:
        text = f.read()
    return text.split("## Python: `import polyroll`", 1)[1].split("\n## ", 1)[0]


def paragraphs():
    """The section's prose (code blocks left out) as (lead, text): each bullet with the name its bold
    lead gives ("- **`Simulation`** steps..." -> "Simulation"), and the introduction with lead ""."""
    prose = re.sub(r"```.*?```", "", python_section(), flags=re.S)
    parts = re.split(r"\n- ", prose)
    out = [("", parts[0])]
    for part in parts[1:]:
        lead = re.match(r"\*\*`?([^*`]+?)`?\*\*", part)
        out.append((lead.group(1) if lead else "", part))
    return out


@pytest.fixture(scope="module")
def documented_objects(tmp_path_factory):
    """One of each object the guide describes, cheap: a Result, a Simulation with grains, a SweepResult."""
    folder = tmp_path_factory.mktemp("docs-sweep") / "s"
    return {
        "run": polyroll.run(fill=0.0, time_limit=SHORT_S),
        "Simulation": polyroll.Simulation(sides=6, fill=0.25, time_limit=SHORT_S),
        "sweep": polyroll.sweep(folder, fill=0.0, angle="10,20", time_limit=SHORT_S, jobs=1),
    }


def accepted_keywords():
    """Every keyword some public call takes: the scene keywords and the calls' own parameters."""
    names = {row["keyword"] for row in polyroll.scene_keywords()}
    for call in (polyroll.scene, polyroll.run, polyroll.Simulation, polyroll.sweep, polyroll.Result.save,
                 polyroll.Result.to_pandas, polyroll.Simulation.step):
        names |= set(inspect.signature(call).parameters)
    return names | {"set"}  # fields=' old name, documented as deprecated


def test_every_name_the_guide_documents_exists_and_runs(documented_objects):
    checked = []
    # polyroll.NAME anywhere in the section, its code included.
    for name in set(re.findall(r"\bpolyroll\.([A-Za-z_]\w*)", python_section())):
        assert hasattr(polyroll, name), f"docs/guide.md documents polyroll.{name}, which the module lacks"
        checked.append(f"polyroll.{name}")
    keywords = accepted_keywords()
    for lead, text in paragraphs():
        if text.startswith("A notebook"):
            continue  # the notebook's own names (its argument `out`): its test executes it
        # A bullet on run, Simulation or sweep documents that object's names; others any of them.
        owners = [documented_objects[lead]] if lead in documented_objects else list(documented_objects.values())
        for token in re.findall(r"`([^`]+)`", text):
            keyword = re.match(r"^([a-z_]\w*)=", token)
            if keyword:
                assert keyword.group(1) in keywords, f"docs/guide.md documents the keyword {token}, which no call takes"
                checked.append(token)
                continue
            name = re.match(r"^\.?([A-Za-z_]\w*)(\(\))?$", token)
            if not name or name.group(1) in NOT_THE_MODULES or hasattr(builtins, name.group(1)):
                continue
            attr, called = name.group(1), bool(name.group(2))
            if not called and hasattr(polyroll, attr):
                checked.append(token)
                continue
            having = [o for o in owners if hasattr(o, attr)]
            assert having, f"docs/guide.md documents {token} ({text[:40]!r}...), which nothing has"
            for owner in having:
                value = getattr(owner, attr)  # a property runs here
                if called:
                    value()  # a method the guide shows called without arguments runs so
            checked.append(token)
    assert {"polyroll.run", "measured()", "shell()", ".to_pandas()", "behaviour", "jobs="} <= set(checked)


def test_the_guides_error_messages_are_the_modules():
    messages = []
    for bad in (dict(sidez=6), dict(angle="x"), dict(sides=99), dict(fill=None)):
        with pytest.raises((TypeError, ValueError)) as e:
            polyroll.run(**bad)
        messages.append(str(e.value))
    errors = next(text for lead, text in paragraphs() if lead.startswith("Errors"))
    quoted = re.findall(r'"([^"]{20,})"', errors.replace("\n  ", " "))
    assert len(quoted) >= 3
    for q in quoted:
        assert any(q in m for m in messages), f"docs/guide.md quotes {q!r}, which the module does not say"


def python_snippets():
    for path in sorted(glob.glob(os.path.join(SOURCE, "docs", "**", "*.md"), recursive=True)):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for k, block in enumerate(re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)):
            yield pytest.param(block, id=f"{os.path.relpath(path, SOURCE)}#{k + 1}")


@pytest.fixture
def short_runs(monkeypatch):
    """run(), Simulation() and sweep() with time_limit=SHORT_S wherever a snippet gives none."""
    run, sweep = polyroll.run, polyroll.sweep

    class ShortSimulation(polyroll.Simulation):
        def __init__(self, *args, **keywords):
            keywords.setdefault("time_limit", SHORT_S)
            super().__init__(*args, **keywords)

    monkeypatch.setattr(polyroll, "run", lambda *a, **k: run(*a, **dict({"time_limit": SHORT_S}, **k)))
    monkeypatch.setattr(polyroll, "sweep", lambda *a, **k: sweep(*a, **dict({"time_limit": SHORT_S}, **k)))
    monkeypatch.setattr(polyroll, "Simulation", ShortSimulation)


def test_docs_hold_python_snippets():
    assert len(list(python_snippets())) >= 1


@pytest.mark.parametrize("code", python_snippets())
def test_every_python_snippet_in_docs_runs_as_written(code, short_runs, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # what a snippet writes (runs/, sweeps/) goes here
    exec(compile(code, "snippet", "exec"), {"__name__": "__snippet__"})  # noqa: S102 (the docs' own code)
