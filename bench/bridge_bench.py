"""Benchmark the Python <-> Prolog bridge and record the figures.

Measures, on this machine:

* the round trip of a trivial operation (``ping``) through ``api:api_request/2``;
* encoding a 20-literal clause to Prolog text and decoding its 20-literal JSON reply
  (pure Python), and its full round trip through Prolog (``echo``);
* a ``clause_lgg`` of two 20-literal example clauses through the bridge, next to the
  same LGG timed inside Prolog, so the bridge's share is visible;
* the resident memory growth over many *distinct* requests (pyswip's own query path
  grows with every new query text; the constant-query bridge must not).

Writes ``bench/results/bridge.json`` and prints a table. Run:
``.venv/bin/python bench/bridge_bench.py [--repeat N]``.
"""

from __future__ import annotations

import argparse
import json
import platform
import random
import resource
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from creative_py.bridge import Compound, Engine, clause, clause_parts, decode, encode  # noqa: E402
from recording import add_output_options, write_figures  # noqa: E402


def example_clause(rng: random.Random, tool: str, n_literals: int = 20) -> Compound:
    """Return a ground tool-use example ``tool_pose(Tool, target1, context1) :- 20 literals``."""
    body = [Compound("hook_like", (tool,)), Compound("hook", (tool,))]
    kinds = [
        lambda: Compound("handle_length_m", (tool, round(rng.uniform(0.1, 0.7), 3))),
        lambda: Compound("hook_side", (tool, rng.choice(["left", "right"]))),
        lambda: Compound("pose", ("target1", round(rng.uniform(0.8, 1.0), 4),
                                  round(rng.uniform(-0.01, 0.01), 4), -0.01, 0.0)),
        lambda: Compound("behind", (tool, "target1")),
        lambda: Compound("near", (tool, rng.choice(["target1", "context1"]))),
        lambda: Compound("size", ("target1", 0.03, 0.03, 0.03)),
        lambda: Compound("tip_position", (tool, round(rng.uniform(0.9, 1.1), 4), 0.0, 0.0)),
    ]
    while len(body) < n_literals:
        body.append(rng.choice(kinds)())
    return clause(Compound("tool_pose", (tool, "target1", "context1")), body)


def timed(fn, repeat: int) -> dict:
    """Return median, mean and p95 of ``repeat`` calls of ``fn`` in microseconds."""
    for _ in range(min(50, repeat)):
        fn()
    samples = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        samples.append((time.perf_counter() - start) * 1e6)
    samples.sort()
    return {
        "median_us": round(statistics.median(samples), 2),
        "mean_us": round(statistics.fmean(samples), 2),
        "p95_us": round(samples[int(0.95 * (len(samples) - 1))], 2),
        "n": repeat,
    }


def rss_kib() -> int:
    """Return the current resident set size in KiB (Linux /proc, else peak RSS)."""
    status = Path("/proc/self/status")
    if status.exists():
        for line in status.read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=2000, help="calls per measurement")
    parser.add_argument("--distinct", type=int, default=20000,
                        help="distinct requests for the memory check")
    add_output_options(parser, "bridge.json", "the timings and memory growth (JSON)")
    args = parser.parse_args()

    start = time.perf_counter()
    engine = Engine.instance()
    startup_s = time.perf_counter() - start

    rng = random.Random(0)
    c1 = example_clause(rng, "tool_1")
    c2 = example_clause(rng, "tool_2")
    c1_text = encode(c1)
    reply_text = engine.request_text(encode(Compound("echo", (c1,))))
    lgg_reply_text = engine.request_text(encode(Compound("clause_lgg", (c1, c2))))
    lgg = decode(lgg_reply_text).args[0]

    results = {
        "ping_round_trip": timed(engine.ping, args.repeat),
        "encode_20_literal_clause": timed(lambda: encode(c1), args.repeat),
        "decode_20_literal_reply": timed(lambda: decode(reply_text), args.repeat),
        "echo_20_literal_clause_round_trip": timed(lambda: engine.call("echo", c1), args.repeat),
        "clause_lgg_20_literals_via_bridge": timed(lambda: engine.clause_lgg(c1, c2),
                                                   max(200, args.repeat // 4)),
    }
    # The same LGG timed inside Prolog (no parsing, no JSON, no Python): the
    # difference to the bridge figure is the bridge's cost.
    n_inside = max(200, args.repeat // 4)
    per_call_s = engine.call("timed", Compound("clause_lgg", (c1, c2)), n_inside)
    results["clause_lgg_20_literals_inside_prolog"] = {
        "mean_us": round(per_call_s * 1e6, 2), "n": n_inside}
    per_ping_s = engine.call("timed", "ping", args.repeat)
    results["ping_inside_prolog"] = {"mean_us": round(per_ping_s * 1e6, 3), "n": args.repeat}

    # Two rounds of distinct requests: the first also grows SWI-Prolog's atom table
    # and heaps once; a leak shows as growth in the second round too.
    rounds = []
    for round_no in range(2):
        rss0 = rss_kib()
        for i in range(args.distinct):
            engine.call("echo", Compound("distinct_request",
                                         (round_no, i, f"atom_{round_no}_{i}", i / 7)))
        rounds.append(rss_kib() - rss0)
    results["memory_distinct_requests"] = {
        "requests_per_round": args.distinct,
        "growth_first_round_kib": rounds[0],
        "growth_second_round_kib": rounds[1],
    }
    results["sizes"] = {
        "clause_text_chars": len(c1_text),
        "echo_reply_json_chars": len(reply_text),
        "lgg_body_literals": len(clause_parts(lgg)[1]),
    }
    results["engine_startup_s"] = round(startup_s, 3)
    results["machine"] = {
        "python": platform.python_version(),
        "swipl": ".".join(map(str, engine.version()["swipl"])),
        "platform": platform.platform(),
    }

    print(f"{'measurement':42s} {'median us':>10s} {'mean us':>10s} {'p95 us':>10s}")
    for name, row in results.items():
        if isinstance(row, dict) and "median_us" in row:
            print(f"{name:42s} {row['median_us']:10.1f} {row['mean_us']:10.1f} "
                  f"{row['p95_us']:10.1f}")
        elif isinstance(row, dict) and "mean_us" in row:
            print(f"{name:42s} {'':>10s} {row['mean_us']:10.1f} {'':>10s}")
    mem = results["memory_distinct_requests"]
    print(f"RSS growth over {mem['requests_per_round']} distinct requests: "
          f"{mem['growth_first_round_kib']} KiB (first round), "
          f"{mem['growth_second_round_kib']} KiB (second round)")
    print(f"engine start (creative.pl loaded): {startup_s:.2f} s")
    write_figures(args, "bridge.json", results, indent=2)


if __name__ == "__main__":
    main()
