"""Mutation testing of the learning, case and report modules (``make mutate``).

Runs mutmut (``pyproject.toml``, ``[tool.mutmut]``: the modules mutated, the quick tests
run against each mutant) and records its counts in ``bench/results/mutation.json``:
killed, survived, timeout, suspicious, no tests, and the score, killed / (all checked
mutants), overall and per module. A whole run takes hours on two cores, so ``--only``
narrows it to some modules (glob patterns of paths, as mutmut's ``only_mutate``) and
``--tests`` to some test files; the JSON names what the run covered, and a narrowed run
is merged into the file by module, so the figures of earlier runs of other modules stay.

Usage::

    python bench/mutation.py                                   # everything configured
    python bench/mutation.py --only creative_py/learning/strategies.py \\
        --tests tests/python/learning/test_learning_stop.py --marks "not slow and not sim"
    python bench/mutation.py --merge ../other-checkout/bench/results/mutation.json
    python bench/mutation.py --reuse --only creative_py/learning/options.py \\
        --tests tests/python/learning/test_run_exact.py \\
        --mutants 'creative_py.learning.options.x_read_run_json__mutmut_*'   # some mutants

The score counts the mutants checked; a narrowed run leaves the others ``not_checked``.
Each mutant runs in a child of mutmut's fork server (``process_isolation``): a child
forked from a process that has started the Prolog engine cannot use that engine.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import random
import shutil
import sys
import time
from datetime import datetime, timezone
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
from recording import add_output_options, write_figures  # noqa: E402

RESULTS = ROOT / "bench" / "results" / "mutation.json"
"""The tracked figures: read as the earlier runs (the modules not run now keep their
counts), written only under --record (or to --out)."""

# mutmut's exit codes of a mutant's test run (mutmut.stats.status_by_exit_code).
KILLED, SURVIVED = {1, 3, 37}, {0}
TIMEOUT, NO_TESTS, NOT_CHECKED = {36, 24, -24, 152, 255}, {5, 33}, {None}


EQUIVALENT = {
    # Surviving mutants judged equivalent by reading them (the names are mutmut's and
    # hold for the source they were read on; a changed function renumbers its mutants).
    "creative_py.report.contents.x__read_json__mutmut_3":
        "encoding None reads the locale's, UTF-8 on every machine the project runs on",
    "creative_py.report.contents.x__read_json__mutmut_5": "'UTF-8' names 'utf-8'",
    "creative_py.report.contents.x_clause_parts__mutmut_6":
        "without ':-' the body is '', and split_top_level('') is [] anyway",
    "creative_py.report.contents.x_relative_inside__mutmut_4":
        "root / an absolute path is that absolute path",
    "creative_py.report.table.x_natural_width__mutmut_3":
        "a console 100001 columns wide measures a table as one 100000 wide does",
    **{f"creative_py.report.table.x_trial_blocks__mutmut_{n}":
       "the outcome style's default: a trial record's outcome is one of the five styled "
       "ones (records.trial refuses any other, read or built in code)"
       for n in (32, 34, 35, 36)},
    "creative_py.report.table.x_print_report__mutmut_33":
        "Rich reads style names in any case: 'ITALIC' is 'italic'",
    "creative_py.report.progress.xǁRunProgressǁ__init____mutmut_25":
        "4 refreshes a second is rich.live.Live's default",
    "creative_py.report.plot.x_plot_trials__mutmut_181":
        "fontsize None is matplotlib's font.size, 10, the size asked",
    "creative_py.report.plot.x_plot_trials__mutmut_204":
        "plt.close(None) closes the current figure, the one just saved",
    **{f"creative_py.report.plot.x_plot_trials__mutmut_{n}":
       "matplotlib reads backend names in any case" for n in (4, 5)},
    **{f"creative_py.report.plot.x_plot_trials__mutmut_{n}":
       "a patch's default colour is C0, tab:blue, and colour names are read in any case"
       for n in (83, 88, 98)},
    **{f"creative_py.report.plot.x_plot_trials__mutmut_{n}":
       "the outcome marker's default: a trial record's outcome is one of the five "
       "(records.trial refuses any other)" for n in (44, 46)},
    **{f"creative_py.report.plot.x_trial_labels__mutmut_{n}":
       "the phase tag's default: a trial record's phase is use, create or eval "
       "(records.trial refuses any other)" for n in (10, 11, 12)},
    **{f"creative_py.fabrication.strength.x_check_strength__mutmut_{n}":
       "the verdict given at construction is a placeholder, replaced before the return"
       for n in (97, 108)},
    **{f"creative_py.fabrication.strength.x_check_strength__mutmut_{n}":
       "every load model's stress is linear in the force with a positive lever or area: "
       "a stress of 0 comes with a force of 0 and a positive force with a positive stress"
       for n in (110, 113, 115)},
    **{f"creative_py.fabrication.strength.x_write_strength__mutmut_{n}":
       "encoding None or no encoding reads the locale's, UTF-8 on every machine the "
       "project runs on; 'UTF-8' names 'utf-8'" for n in (5, 7, 18, 21, 25)},
    **{f"creative_py.fabrication.strength.x_write_strength__mutmut_{n}":
       "the temporary file's prefix: it is renamed over the JSON or removed, never seen"
       for n in (12, 14)},
    **{f"creative_py.fabrication.strength.x_write_strength__mutmut_{n}":
       "on the failure path the temporary file exists (mkstemp made it), so missing_ok "
       "is never used" for n in (44, 46)},
    "creative_py.fabrication.strength.xǁStrengthCheckǁto_dict__mutmut_1":
        "every call of r() in to_dict names its digits: the default is never used",
    # creative_py/fabrication/manufacture.py
    **{f"creative_py.fabrication.manufacture.x__did_you_mean__mutmut_{n}":
       "difflib.get_close_matches lists the best match first whatever n (>= 1) is, and "
       "only close[0] is used" for n in (7, 9)},
    "creative_py.fabrication.manufacture.x_parse_context__mutmut_3":
        "Prolog reads '[' + blank text + ']' as [], the else branch's value",
    "creative_py.fabrication.manufacture.x_tool_vocabulary__mutmut_2":
        "a process has one engine (Engine refuses a second), so id(None) in place of "
        "id(engine) keys the same one vocabulary per case",
    # creative_py/learning/options.py and run.py (read_run, _tools, headline and
    # _earlier_summary were rewritten for the typed summary: their mutants are renumbered
    # and are judged again on the next run)
    **{f"creative_py.learning.options.x_read_run_json__mutmut_{n}":
       "encoding None reads the locale's, UTF-8 on every machine the project runs on; "
       "'UTF-8' names 'utf-8'" for n in (10, 12)},
    "creative_py.learning.run.x_resume_run__mutmut_20":
        "logging %-formats a message only when it has arguments: log.warning(w) logs w "
        "as log.warning('%s', w) does",
    "creative_py.learning.run.x_resume_run__mutmut_25":
        "run_case uses out only for a new run's folder; a resume's folder is given whole",
    # creative_py/learning/creation.py
    **{f"creative_py.learning.creation.xǁToolCreatorǁ{name}__mutmut_{n}":
       "a created tool's trial outcome placeholder: the trial's outcome replaces it before "
       "anything reads it (a trial that raises leaves create() with no result)"
       for name, n in (("_make_and_try", 20), ("_make_and_try", 39), ("_strengthen", 71),
                       ("_strengthen", 87))},
    # learning/clips.py
    **{f"creative_py.learning.clips.xǁClipKeeperǁ__init____mutmut_{n}":
       "prepare() only imports the encoder and loads the font ahead of the clips (a "
       "forked clip process inherits them): every clip is the same whether or not it ran"
       for n in (39, 40, 41)},
    **{f"creative_py.learning.clips.xǁClipKeeperǁ_note__mutmut_{n}":
       "json.dumps writes ASCII only (ensure_ascii): every encoding writes the same bytes"
       for n in (11, 14, 18)},
    **{f"creative_py.learning.clips.xǁClipKeeperǁ_earlier_entries__mutmut_{n}":
       "clips.jsonl holds ASCII JSON (_note), read the same in any ASCII-compatible "
       "encoding; 'UTF-8' names 'utf-8'" for n in (3, 6)},
    # learning/trials.py
    "creative_py.learning.trials.x_task_facts__mutmut_13":
        "robot=None builds no robot, as robot=False (the episode tests its truth)",
    "creative_py.learning.trials.x_task_facts__mutmut_18": "seed 0 is open_episode's default",
    **{f"creative_py.learning.trials.x_task_facts__mutmut_{n}":
       "a scene with the robot gives the same facts (the cameras do not see it, it holds "
       "nothing), only later" for n in (19, 23)},
    "creative_py.learning.trials.xǁTrialRunnerǁ_label__mutmut_22":
        "a blocked trial's planned example takes only the tool's parts from the facts "
        "(experiment:label_trial/7), and its catalogue facts where the motion stopped "
        "are the task's",
    "creative_py.learning.trials.xǁTrialRunnerǁend_replay__mutmut_3":
        "held is only tested for its truth (ClipKeeper.write): None is False",
    "creative_py.learning.trials.xǁTrialRunnerǁrun__mutmut_61":
        "a trial tests one literal at most (_planned): the separator is never written",
}
"""Mutants that no test can kill: the code means the same with them."""


def classify(code: int | None) -> str:
    """Return the status of one mutant from mutmut's recorded exit code."""
    if code in KILLED:
        return "killed"
    if code in SURVIVED:
        return "survived"
    if code in TIMEOUT:
        return "timeout"
    if code in NO_TESTS:
        return "no_tests"
    if code in NOT_CHECKED:
        return "not_checked"
    return "suspicious"


def tally(exit_codes: dict[str, int | None]) -> dict:
    """Return the counts of each status and the score of mutants' exit codes.

    The score is killed / (killed + survived + timeout + suspicious + no_tests): a
    mutant that no test runs counts as a survivor, one never checked is left out.
    """
    counts = dict.fromkeys(("killed", "survived", "timeout", "suspicious", "no_tests",
                            "not_checked"), 0)
    for code in exit_codes.values():
        counts[classify(code)] += 1
    checked = sum(v for k, v in counts.items() if k != "not_checked")
    counts["score"] = round(counts["killed"] / checked, 4) if checked else None
    return counts


def module_results(mutants: Path) -> dict[str, dict]:
    """Return, by source path, the tally and the surviving mutants' names."""
    out = {}
    for meta in sorted(mutants.rglob("*.py.meta")):
        source = meta.relative_to(mutants).as_posix()[: -len(".meta")]
        codes = json.loads(meta.read_text())["exit_code_by_key"]
        if not codes:
            continue
        entry = tally(codes)
        entry["survivors"] = sorted(k for k, v in codes.items()
                                    if classify(v) in ("survived", "no_tests", "suspicious"))
        entry["equivalent"] = [k for k in entry["survivors"] if k in EQUIVALENT]
        entry["score_non_equivalent"] = _score(entry, len(entry["equivalent"]))
        out[source] = entry
    return out


def configured_modules() -> list[str]:
    """Return the source files ``[tool.mutmut] only_mutate`` names that hold code (not
    an ``__init__.py`` of imports alone), relative to the project."""
    import tomllib
    from fnmatch import fnmatch

    globs = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["mutmut"][
        "only_mutate"]
    files = sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "creative_py").rglob("*.py"))
    return [f for f in files if any(fnmatch(f, g) for g in globs)
            and "def " in (ROOT / f).read_text()]


def _score(counts: dict, equivalent: int) -> float | None:
    """Return killed / (checked mutants less the equivalent ones)."""
    checked = sum(counts[k] for k in ("killed", "survived", "timeout", "suspicious",
                                      "no_tests")) - equivalent
    return round(counts["killed"] / checked, 4) if checked > 0 else None


def run_mutmut(only: list[str], tests: list[str], max_children: int | None,
               marks: str | None = None, names: list[str] | None = None) -> None:
    """Run ``mutmut run`` in this process with the configuration narrowed as asked
    (``names``: only the mutants of these names, ``*`` a wildcard)."""
    os.chdir(ROOT)
    import mutmut.configuration as configuration

    config = configuration._load_config()
    changes = {}
    if only:
        changes["only_mutate"] = only
    if tests:
        changes["pytest_add_cli_args_test_selection"] = tests
    if marks:
        args = list(config.pytest_add_cli_args)
        if "-m" in args:
            args[args.index("-m") + 1] = marks
        else:
            args += ["-m", marks]
        changes["pytest_add_cli_args"] = args
    configuration._config = dataclasses.replace(config, **changes)
    from mutmut.__main__ import cli

    args = ["run"] + (["--max-children", str(max_children)] if max_children else [])
    args += names or []
    try:
        cli.main(args, standalone_mode=False)
    except SystemExit as stop:
        if stop.code not in (0, None):
            raise


def mutant_names(source: str) -> list[str]:
    """Return the names mutmut gives the mutants of one source file, in its order."""
    import io

    from mutmut.__main__ import write_all_mutants_to_file

    path = ROOT / source
    made = write_all_mutants_to_file(out=io.StringIO(), source=path.read_text(),
                                     filename=Path(source))
    module = source.removesuffix(".py").replace("/", ".")
    return [n if n.startswith(module + ".") else f"{module}.{n}" for n in made.mutant_names]


def sample_entry(source: str, names: list[str], seed: int, of: int) -> dict:
    """Return the tally of a random sample's mutants (those of ``names`` that mutmut
    checked) with the score's 95 % Wilson interval, an estimate of the whole module."""
    codes = json.loads((ROOT / "mutants" / f"{source}.meta").read_text())["exit_code_by_key"]
    chosen = {k: v for k, v in codes.items() if k in names}
    entry = tally(chosen)
    entry["survivors"] = sorted(k for k, v in chosen.items()
                                if classify(v) in ("survived", "no_tests", "suspicious"))
    entry["equivalent"] = [k for k in entry["survivors"] if k in EQUIVALENT]
    entry["score_non_equivalent"] = _score(entry, len(entry["equivalent"]))
    n = sum(entry[k] for k in ("killed", "survived", "timeout", "suspicious", "no_tests")) \
        - len(entry["equivalent"])
    if n:
        p, z = entry["killed"] / n, 1.96
        centre = (p + z * z / (2 * n)) / (1 + z * z / n)
        half = z * ((p * (1 - p) / n + z * z / (4 * n * n)) ** 0.5) / (1 + z * z / n)
        entry["interval95_non_equivalent"] = [round(centre - half, 4), round(centre + half, 4)]
    entry.update(sample=len(names), seed=seed, of=of)
    return entry


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", action="append", default=[],
                        help="a glob of source paths to mutate (repeatable)")
    parser.add_argument("--tests", action="append", default=[],
                        help="a test path to run against the mutants (repeatable)")
    parser.add_argument("--marks", default=None,
                        help="pytest's -m for the mutants' test runs, in place of the "
                             "configured 'not slow' (e.g. 'not slow and not sim': no "
                             "physics)")
    parser.add_argument("--max-children", type=int, default=None,
                        help="mutmut's parallel test processes (default: mutmut's, one "
                             "a core)")
    parser.add_argument("--label", default=None,
                        help="a note stored with the figures (e.g. 'before the new tests')")
    parser.add_argument("--mutants", action="append", default=[],
                        help="run only the mutants of this name (repeatable; '*' a "
                             "wildcard, e.g. 'creative_py.learning.options.x_read_run_json*'); "
                             "with --reuse, the others keep their results, and a mutant "
                             "never run counts as not checked")
    parser.add_argument("--sample", type=int, default=None,
                        help="run a random sample of this many mutants of the one --only "
                             "module and record it under 'samples' (an estimate with its "
                             "95 %% interval), leaving the module's recorded counts as "
                             "they are; for modules whose every mutant costs a whole "
                             "replayed run")
    parser.add_argument("--seed", type=int, default=1, help="the seed of --sample")
    parser.add_argument("--reuse", action="store_true",
                        help="keep mutants/ and mutmut's results of the last run (only "
                             "with the same --only: mutmut does not mutate again a "
                             "file it copied unmutated)")
    parser.add_argument("--merge", action="append", default=[], type=Path,
                        help="run nothing: take the modules and history of another "
                             "results file (a narrowed run made in another checkout); a "
                             "module recorded in both keeps its later run (repeatable)")
    parser.add_argument("--summarise", action="store_true",
                        help="run nothing: recompute the totals and the equivalent "
                             "mutants of the recorded modules")
    add_output_options(parser, "mutation.json", "the scores (JSON, with the other modules' "
                                                "recorded counts)")
    args = parser.parse_args(argv)
    if args.merge:
        args.summarise = True
    if not args.reuse and not args.summarise:
        shutil.rmtree(ROOT / "mutants", ignore_errors=True)
    start = time.monotonic()
    sampled, population = None, 0
    if args.sample:
        if len(args.only) != 1 or "*" in args.only[0]:
            parser.error("--sample needs one --only module file")
        names = mutant_names(args.only[0])
        population = len(names)
        args.mutants = random.Random(args.seed).sample(names, min(args.sample, population))
        sampled = args.only[0]
    if args.summarise:
        modules = {}
    else:
        run_mutmut(args.only, args.tests, args.max_children, args.marks, args.mutants)
        modules = {} if sampled else module_results(ROOT / "mutants")
    if args.only:
        from fnmatch import fnmatch
        modules = {k: v for k, v in modules.items() if any(fnmatch(k, p) for p in args.only)}
    previous = json.loads(RESULTS.read_text()) if RESULTS.exists() else {}
    merged = dict(previous.get("modules", {}))
    history = list(previous.get("history", []))
    stamp = datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%MZ")
    samples = dict(previous.get("samples", {}))
    if sampled:
        samples[sampled] = {"at": stamp, "label": args.label, "tests": args.tests,
                            **sample_entry(sampled, args.mutants, args.seed, population)}
    for other in args.merge:
        theirs = json.loads(other.read_text())
        for source, entry in theirs.get("samples", {}).items():
            if source not in samples or entry["at"] > samples[source]["at"]:
                samples[source] = entry
        for source, entry in theirs.get("modules", {}).items():
            if source not in merged or entry["run"]["at"] > merged[source]["run"]["at"]:
                merged[source] = entry
        history += [h for h in theirs.get("history", []) if h not in history]
    history.sort(key=lambda h: h["at"])
    for source, entry in modules.items():
        entry["run"] = {"at": stamp, "tests": args.tests or "pyproject [tool.mutmut]",
                        "marks": args.marks or "not slow", "label": args.label}
        merged[source] = entry
    for entry in merged.values():  # the equivalent mutants as this file knows them now
        entry["equivalent"] = [k for k in entry["survivors"] if k in EQUIVALENT]
        entry["score_non_equivalent"] = _score(entry, len(entry["equivalent"]))
    totals = {k: sum(m[k] for m in merged.values())
              for k in ("killed", "survived", "timeout", "suspicious", "no_tests",
                        "not_checked")}
    checked = sum(v for k, v in totals.items() if k != "not_checked")
    totals["score"] = round(totals["killed"] / checked, 4) if checked else None
    totals["equivalent"] = sum(len(m.get("equivalent", [])) for m in merged.values())
    totals["score_non_equivalent"] = _score(totals, totals["equivalent"])
    result = {
        "tool": "mutmut",
        "configured": "pyproject.toml [tool.mutmut]: creative_py/learning/, "
                      "creative_py/case.py, creative_py/report/",
        "modules_covered": sorted(merged),
        # Configured modules with code to mutate that no recorded run covers: the total
        # is not the whole configured score while this list is not empty.
        "modules_not_run": [m for m in configured_modules() if m not in merged],
        "total": totals,
        "modules": merged,
        "equivalent": {k: v for k, v in EQUIVALENT.items()
                       if any(k in m["equivalent"] for m in merged.values())},
        # Random samples of modules too dear to run whole: estimates, kept apart from the
        # modules' counts (``--sample``); a module's latest sample replaces its earlier.
        "samples": samples,
        "history": history + ([] if args.summarise else [{
            "at": stamp, "only": args.only or "all configured", "label": args.label,
            **({"mutants": args.mutants} if args.mutants else {}),
            "tests": args.tests or "pyproject [tool.mutmut]", "marks": args.marks or "not slow",
            "seconds": round(time.monotonic() - start),
            "modules": {k: {s: v[s] for s in ("killed", "survived", "timeout",
                                              "suspicious", "no_tests", "score",
                                              "score_non_equivalent")}
                        for k, v in modules.items()}}]),
    }
    if sampled:
        print(f"sample of {sampled}: {samples[sampled]['killed']} of "
              f"{samples[sampled]['sample']} killed, non-equivalent score "
              f"{samples[sampled]['score_non_equivalent']} "
              f"(95 % interval {samples[sampled].get('interval95_non_equivalent')})")
    print(f"mutation score {totals['score']} ({totals['score_non_equivalent']} of the "
          f"non-equivalent mutants) over {', '.join(sorted(merged))}")
    write_figures(args, "mutation.json", result, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
