"""The documentation's figures about runs equal what ``bench/results`` records.

``bench/readme_figures.py`` writes two files: the README's own marked blocks
(``<!-- figures:NAME -->``) and ``docs/results.md``, generated whole from its template
``docs/results.md.in``. Both are regenerated in memory from ``bench/results/*.json`` and
compared with the files; a block that differs, is missing or is written twice fails,
naming the block (run ``make readme-figures`` after re-running a benchmark,
``bench/test_time.py`` included, or after editing the template).
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
TEMPLATE = (ROOT / "docs" / "results.md.in").read_text(encoding="utf-8")
PAGE = (ROOT / "docs" / "results.md").read_text(encoding="utf-8")
WANT_PAGE = FIGURES.results_page(TEMPLATE)
PAGE_BLOCKS = sorted(set(FIGURES.BLOCKS) - FIGURES.README_BLOCKS)


@pytest.mark.parametrize("name", sorted(FIGURES.README_BLOCKS))
def test_the_readme_block_equals_its_figures(name):
    want = FIGURES.render()[name]
    have = FIGURES.blocks_in(README).get(name, [])
    assert len(have) == 1, (f"README block {name}: found {len(have)} times, want once "
                            f"(<!-- figures:{name} --> ... <!-- /figures:{name} -->)")
    assert have[0] == want, (f"README block {name} differs from bench/results: run "
                             f"make readme-figures\n--- README\n{have[0]}\n--- results\n{want}")


@pytest.mark.parametrize("name", PAGE_BLOCKS)
def test_the_results_page_block_equals_its_figures(name):
    want = FIGURES.blocks_in(WANT_PAGE)[name]
    have = FIGURES.blocks_in(PAGE).get(name, [])
    assert len(have) == 1, (f"docs/results.md block {name}: found {len(have)} times, "
                            f"want once")
    assert have == want, (f"docs/results.md block {name} differs from bench/results: run "
                          f"make readme-figures\n--- page\n{have[0]}\n--- results\n{want[0]}")


def test_the_results_page_is_its_template_filled():
    assert FIGURES.page_disagreements(PAGE, WANT_PAGE) == []
    assert PAGE == WANT_PAGE, "docs/results.md differs from docs/results.md.in: run make readme-figures"


def test_every_block_has_a_function_and_one_page():
    unknown = sorted(set(FIGURES.blocks_in(README)) - FIGURES.README_BLOCKS)
    assert unknown == [], f"README blocks no README function writes: {unknown}"
    in_template = FIGURES.blocks_in(TEMPLATE)
    assert sorted(in_template) == PAGE_BLOCKS
    assert all(len(v) == 1 for v in in_template.values())
    assert not FIGURES.README_BLOCKS & set(in_template)


def test_the_results_page_says_it_is_generated():
    assert PAGE.startswith(FIGURES.GENERATED_NOTE)
    assert "<!-- TEMPLATE" not in PAGE and TEMPLATE.startswith("<!-- TEMPLATE")
    assert "{" not in "".join(b[0] for b in FIGURES.blocks_in(PAGE).values()
                              if "```" not in b[0]), "a placeholder left unfilled"


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


def test_a_changed_page_is_named():
    name = PAGE_BLOCKS[0]
    changed = WANT_PAGE.replace(f"<!-- figures:{name} -->\n", f"<!-- figures:{name} -->\n7 ", 1)
    assert FIGURES.page_disagreements(changed, WANT_PAGE) == [
        f"block {name}: docs/results.md differs from bench/results (run make readme-figures)"]
    prose = WANT_PAGE.replace("# Results", "# Results!", 1)
    assert FIGURES.page_disagreements(prose, WANT_PAGE) == [
        "docs/results.md differs from docs/results.md.in outside the blocks (edit the "
        "template, then run make readme-figures)"]


def test_a_template_block_is_filled_from_its_values():
    assert FIGURES.fill("{a[b]:.1f} of {c}", {"a": {"b": 2.25}, "c": 4}) == "2.2 of 4"
    assert FIGURES.fill("{text}", "| x |\n") == "| x |"
    with pytest.raises(RuntimeError, match="block nope of results.md.in"):
        FIGURES.results_page("<!-- figures:nope -->\n{text}\n<!-- /figures:nope -->\n")
    errors = []
    FIGURES.results_page("no blocks\n", errors)
    assert errors[0] == f"block {PAGE_BLOCKS[0]}: missing from results.md.in"


def test_rewrite_puts_the_figures_between_the_marks():
    text = "a\n<!-- figures:x -->\nold 1\nold 2\n<!-- /figures:x -->\nb\n"
    assert FIGURES.rewrite(text, {"x": "new"}) == (
        "a\n<!-- figures:x -->\nnew\n<!-- /figures:x -->\nb\n")
    assert FIGURES.blocks_in(text) == {"x": ["old 1\nold 2"]}
