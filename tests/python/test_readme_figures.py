"""The README's figures about runs equal what ``bench/results`` records.

Each marked block ``<!-- figures:NAME -->`` of ``README.md`` is regenerated in memory by
``bench/readme_figures.py`` from ``bench/results/*.json`` and compared with the README;
a block that differs, is missing or is written twice fails, naming the block (run
``make readme-figures`` after re-running a benchmark, ``bench/test_time.py`` included).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "bench" / "readme_figures.py"


def _figures():
    spec = importlib.util.spec_from_file_location("readme_figures", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


FIGURES = _figures()
README = (ROOT / "README.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("name", sorted(FIGURES.BLOCKS))
def test_the_readme_block_equals_its_figures(name):
    want = FIGURES.BLOCKS[name]().rstrip("\n")
    have = FIGURES.blocks_in(README).get(name, [])
    assert len(have) == 1, (f"README block {name}: found {len(have)} times, want once "
                            f"(<!-- figures:{name} --> ... <!-- /figures:{name} -->)")
    assert have[0] == want, (f"README block {name} differs from bench/results: run "
                             f"make readme-figures\n--- README\n{have[0]}\n--- results\n{want}")


def test_every_block_of_the_readme_has_a_function():
    unknown = sorted(set(FIGURES.blocks_in(README)) - set(FIGURES.BLOCKS))
    assert unknown == [], f"README blocks no function of bench/readme_figures.py writes: {unknown}"


def test_a_changed_figure_is_named():
    rendered = FIGURES.render([])
    name = sorted(rendered)[0]
    text = FIGURES.rewrite(README, rendered)
    assert FIGURES.disagreements(text, rendered) == []
    changed = text.replace(f"<!-- figures:{name} -->\n",
                           f"<!-- figures:{name} -->\n7 ", 1)
    assert FIGURES.disagreements(changed, rendered) == [
        f"block {name}: the README differs from bench/results (run make readme-figures)"]
    gone = FIGURES.BLOCK.sub("", text, count=1)
    first = FIGURES.BLOCK.search(text).group(1)
    assert FIGURES.disagreements(gone, rendered) == [
        f"block {first}: missing from the README"]


def test_rewrite_puts_the_figures_between_the_marks():
    text = "a\n<!-- figures:x -->\nold 1\nold 2\n<!-- /figures:x -->\nb\n"
    assert FIGURES.rewrite(text, {"x": "new"}) == (
        "a\n<!-- figures:x -->\nnew\n<!-- /figures:x -->\nb\n")
    assert FIGURES.blocks_in(text) == {"x": ["old 1\nold 2"]}
