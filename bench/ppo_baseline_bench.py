"""A PPO baseline on ManiSkill3's PullCubeTool-v1: success rate against environment steps.

    python bench/ppo_baseline_bench.py [--budget STEPS] [--num-envs 16] [--num-steps 200]
        [--eval-every STEPS] [--eval-episodes 50] [--eval-seed 20000] [--seed 0]
        [--out bench/results/ppo_baseline.json] [--plot bench/results/ppo_baseline.png]

(``make bench-rl``: installs the ``rl`` extra on top of the ``maniskill`` one and runs this
niced.) Not a test: a fixed budget of environment steps, chosen so the run fits the machine
(``--budget``; someone with time can give millions).

What runs: stable-baselines3's PPO on ManiSkill's own ``PullCubeTool-v1`` (the stock task
and tool, ``obs_mode="state"``, ``control_mode="pd_joint_delta_pos"``, reward
``normalized_dense``, CPU simulation, ``--num-envs`` environments stepped in this one
process), with the hyperparameters of ManiSkill's CleanRL-style PPO baseline
(``examples/baselines/ppo/ppo.py`` of the ManiSkill repository, and its CPU-simulation
settings of ``ppo_cpu.py``) as far as SB3 has them; :data:`HYPERPARAMETERS` says which
differ and why.

What is measured: every ``--eval-every`` environment steps (and at 0 and at the end) the
deterministic policy (the Gaussian's mean) plays ``--eval-episodes`` episodes on fixed
evaluation seeds ``--eval-seed`` on, one episode a seed (``env.reset(seed=...)``, ManiSkill's
seeded initial state), each until it terminates (ManiSkill ends the episode on success)
or reaches the task's 100 control steps; an episode succeeds when ManiSkill's
``evaluate()`` says ``success`` (``info["success"]``) at its end. Training episodes reset
on seeds of their own (:data:`TRAIN_SEED_BASE` on, environment ``i`` taking ``base + i``,
``base + i + n``, ...), so no training episode starts where an evaluation episode does,
and none on the seeds of CREATIVE-py's figures (learning locations below 100, evaluation
seeds 1000 on, ``worlds/*/tasks.toml`` and ``bench/maniskill_bench.py``). Writes
``bench/results/ppo_baseline.json`` (the curve, the training episodes' success per
interval, the budget, wall times, steps per second, hyperparameters, versions, seeds and
the machine's load) and a plot beside it with CREATIVE-py's figures of
``bench/results/maniskill.json``.
"""

from __future__ import annotations

import argparse
import importlib.metadata as md
import itertools
import json
import math
import os
import platform
import subprocess
import sys
import time
from pathlib import Path
from typing import Any, Iterator

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"

ENV_ID = "PullCubeTool-v1"
"""ManiSkill's task (its stock tool; the learner's runs use the same task class with
catalogued tools, see ``creative_py/backends/maniskill/env.py``)."""

TRAIN_SEED_BASE = 1_000_000
"""The first seed of the training episodes' resets (far from every evaluation seed)."""

HYPERPARAMETERS: dict[str, tuple[Any, str]] = {
    # name: (value, where it comes from / why it differs from ManiSkill's baseline)
    "learning_rate": (3e-4, "ppo.py default"),
    "gamma": (0.8, "ppo.py default"),
    "gae_lambda": (0.9, "ppo.py default"),
    "clip_range": (0.2, "ppo.py clip_coef"),
    "ent_coef": (0.0, "ppo.py default"),
    "vf_coef": (0.5, "ppo.py default"),
    "max_grad_norm": (0.5, "ppo.py default"),
    "target_kl": (0.1, "ppo.py default; SB3 stops an update's epochs at 1.5 x target_kl, "
                       "ppo.py at target_kl"),
    "normalize_advantage": (True, "ppo.py norm_adv"),
    "n_epochs": (8, "update_epochs=8 of every state-based command in examples.sh and of "
                    "ppo_cpu.py (ppo.py's default is 4)"),
    "num_minibatches": (8, "ppo_cpu.py's CPU-simulation setting (GPU settings use 32 "
                           "minibatches of 512-2048 environments' rollouts; with 16 "
                           "environments that would be minibatches of 100)"),
    "num_envs": (16, "ppo_cpu.py's CPU-simulation setting (GPU runs use 512-2048); "
                     "stepped in one process here (SB3's DummyVecEnv): the machine has "
                     "2 cores shared with other users"),
    "num_steps": (200, "ppo_cpu.py's CPU-simulation setting: two of this task's 100-step "
                       "episodes per environment and rollout"),
    "net": ("actor and critic apart, 3 x 256 tanh, orthogonal init", "ppo.py's Agent"),
    "log_std_init": (-0.5, "ppo.py's actor_logstd"),
    "adam_eps": (1e-5, "ppo.py; SB3's default for PPO too"),
    "control_mode": ("pd_joint_delta_pos", "ppo.py default"),
    "reward_mode": ("normalized_dense", "ManiSkill's default for the task"),
    "partial_reset": (True, "ppo.py default: an environment resets when its episode "
                            "ends (SB3's vector environments do)"),
    "truncation_bootstrap": (True, "ppo.py bootstraps the value at a time-limit "
                                   "truncation; SB3 does too"),
    "finite_horizon_gae": (False, "ppo_cpu.py sets it; SB3 has no such option"),
    "reconfiguration_freq": (0, "the task draws no new object at a reset; ppo_cpu.py's 1 "
                                "rebuilds the scene every reset"),
}


class Usage(Exception):
    """Bad input: one line, exit 2."""


def _int(text: str, name: str, low: int = 1) -> int:
    try:
        value = int(text.replace("_", ""))
    except ValueError:
        raise Usage(f"{name}: {text!r} is not a whole number") from None
    if value < low:
        raise Usage(f"{name}: {value} is below {low}")
    return value


def parse(argv: list[str] | None) -> argparse.Namespace:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--budget", default="384000",
                    help="training environment steps (rounded up to whole rollouts)")
    ap.add_argument("--num-envs", default=str(HYPERPARAMETERS["num_envs"][0]),
                    help="parallel ManiSkill environments (default "
                         f"{HYPERPARAMETERS['num_envs'][0]})")
    ap.add_argument("--num-steps", default=str(HYPERPARAMETERS["num_steps"][0]),
                    help="steps per environment and rollout")
    ap.add_argument("--num-minibatches", default=str(HYPERPARAMETERS["num_minibatches"][0]),
                    help="minibatches each rollout is split into for the PPO update "
                         f"(default {HYPERPARAMETERS['num_minibatches'][0]})")
    ap.add_argument("--eval-every", default=None,
                    help="environment steps between evaluations (default: budget / 10)")
    ap.add_argument("--eval-episodes", default="50",
                    help="episodes (fresh seeds) of each evaluation (default 50)")
    ap.add_argument("--eval-seed", default="20000", help="the first evaluation seed")
    ap.add_argument("--seed", default="0", help="PPO's seed (torch, numpy)")
    ap.add_argument("--env-id", default=ENV_ID,
                    help=f"the ManiSkill environment trained on (default {ENV_ID})")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--out", type=Path, default=None, metavar="FILE",
                       help="write the figures (JSON) to FILE and the plot beside it; "
                            "one of --out and --record is needed")
    where.add_argument("--record", action="store_true",
                       help="write them to the tracked bench/results/ppo_baseline.json "
                            "and .png, which docs/results.md is made from")
    ap.add_argument("--plot", type=Path, default=None,
                    help="the plot (default: --out with .png)")
    ap.add_argument("--learner", type=Path, default=RESULTS / "maniskill.json",
                    help="CREATIVE-py's figures (make bench-maniskill) for the plot")
    ap.add_argument("--replot", action="store_true",
                    help="train nothing: draw the plot again from --out's figures")
    a = ap.parse_args(argv)
    if a.out is None and not a.record:
        raise Usage("give --out FILE, or --record to update the tracked "
                    "bench/results/ppo_baseline.json: a tracked file is only overwritten "
                    "when asked")
    a.out = a.out or RESULTS / "ppo_baseline.json"
    a.budget = _int(a.budget, "--budget")
    a.num_envs = _int(a.num_envs, "--num-envs")
    a.num_steps = _int(a.num_steps, "--num-steps")
    a.num_minibatches = _int(a.num_minibatches, "--num-minibatches")
    a.eval_episodes = _int(a.eval_episodes, "--eval-episodes")
    a.eval_seed = _int(a.eval_seed, "--eval-seed", 0)
    a.seed = _int(a.seed, "--seed", 0)
    a.eval_every = (_int(a.eval_every, "--eval-every") if a.eval_every is not None
                    else max(a.num_envs * a.num_steps, a.budget // 10))
    if (a.num_envs * a.num_steps) % a.num_minibatches:
        raise Usage(f"--num-minibatches: {a.num_minibatches} does not divide a rollout of "
                    f"{a.num_envs} x {a.num_steps} steps")
    if a.eval_seed + a.eval_episodes > TRAIN_SEED_BASE:
        raise Usage(f"--eval-seed: the evaluation seeds reach the training seeds "
                    f"({TRAIN_SEED_BASE} on)")
    if a.eval_seed < 2000:
        raise Usage(f"--eval-seed: {a.eval_seed}: seeds below 2000 are CREATIVE-py's "
                    f"learning and evaluation seeds; take fresh ones")
    if a.learner is not None and not a.learner.is_file():
        raise Usage(f"--learner: {a.learner}: no such file")
    if a.replot and not a.out.is_file():
        raise Usage(f"--out: {a.out}: no such file to plot (--replot)")
    a.plot = a.plot or a.out.with_suffix(".png")
    return a


def load() -> str:
    """The machine's load averages as ``uptime`` prints them."""
    try:
        return subprocess.run(["uptime"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "load average: " + ", ".join(f"{v:.2f}" for v in os.getloadavg())


def make_env(env_id: str, control_mode: str, seeds: Iterator[int] | None = None):
    """ManiSkill's task on the CPU simulation as a plain gymnasium environment (numpy
    observations, one episode at a time), resetting on ``seeds`` when given."""
    import logging

    import gymnasium as gym
    import mani_skill.envs  # noqa: F401  (registers the tasks)
    from mani_skill import logger as maniskill_logger
    from mani_skill.utils.wrappers.gymnasium import CPUGymWrapper

    # ManiSkill warns at every environment it builds that no initial pose was set for its
    # builders (its episode initialisation sets them) and that CUDA is missing.
    maniskill_logger.setLevel(logging.ERROR)

    env = gym.make(env_id, obs_mode="state", control_mode=control_mode,
                   reward_mode="normalized_dense", sim_backend="cpu", render_mode=None,
                   reconfiguration_freq=HYPERPARAMETERS["reconfiguration_freq"][0])
    env = CPUGymWrapper(env, ignore_terminations=False, record_metrics=False)
    if seeds is None:
        return env

    class SeededResets(gym.Wrapper):
        """Every reset takes the next seed of its own sequence (SB3's automatic resets
        pass none), so the training episodes' initial states are known seeds."""

        def reset(self, *, seed=None, options=None):
            return self.env.reset(seed=next(seeds), options=options)

    return SeededResets(env)


def evaluate(model, env, seeds: list[int]) -> dict[str, Any]:
    """Play one deterministic episode per seed; ManiSkill's success at each episode's end."""
    outcomes, steps = [], 0
    for seed in seeds:
        obs, _ = env.reset(seed=seed)
        while True:
            action, _ = model.predict(obs, deterministic=True)
            obs, _r, term, trunc, info = env.step(action)
            steps += 1
            if term or trunc:
                break
        outcomes.append(bool(info["success"]))
    return {"successes": sum(outcomes), "episodes": len(seeds),
            "success_rate": sum(outcomes) / len(seeds), "env_steps": steps,
            "succeeded_seeds": [s for s, ok in zip(seeds, outcomes) if ok]}


def env_speed(env_id: str, steps: int = 600) -> float:
    """Environment steps per second of one environment under random actions."""
    env = make_env(env_id, HYPERPARAMETERS["control_mode"][0])
    env.reset(seed=TRAIN_SEED_BASE - 1)
    env.action_space.seed(0)
    t0 = time.perf_counter()
    for _ in range(steps):
        _o, _r, term, trunc, _i = env.step(env.action_space.sample())
        if term or trunc:
            env.reset()
    rate = steps / (time.perf_counter() - t0)
    env.close()
    return rate


def versions() -> dict[str, str]:
    out = {"python": platform.python_version()}
    for dist in ("stable-baselines3", "mani-skill", "sapien", "torch", "gymnasium", "numpy"):
        try:
            out[dist] = md.version(dist)
        except md.PackageNotFoundError:
            out[dist] = "absent"
    return out


def train(a: argparse.Namespace) -> dict[str, Any]:
    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.callbacks import BaseCallback
    from stable_baselines3.common.vec_env import DummyVecEnv

    torch.set_num_threads(1)
    hp = {k: v for k, (v, _) in HYPERPARAMETERS.items()}
    hp.update(num_envs=a.num_envs, num_steps=a.num_steps, num_minibatches=a.num_minibatches)
    rollout = a.num_envs * a.num_steps
    iterations = math.ceil(a.budget / rollout)
    total = iterations * rollout
    eval_seeds = list(range(a.eval_seed, a.eval_seed + a.eval_episodes))
    load_before = load()
    speed = env_speed(a.env_id)
    print(f"one environment, random actions: {speed:.0f} steps/s; {load_before}", flush=True)

    def stream(i: int) -> Iterator[int]:
        return itertools.count(TRAIN_SEED_BASE + i, a.num_envs)

    used = [0] * a.num_envs

    def counting(i: int) -> Iterator[int]:
        for s in stream(i):
            used[i] += 1
            yield s

    t_setup = time.perf_counter()
    venv = DummyVecEnv([(lambda i=i: make_env(a.env_id, hp["control_mode"], counting(i)))
                        for i in range(a.num_envs)])
    eval_env = make_env(a.env_id, hp["control_mode"])
    model = PPO("MlpPolicy", venv, learning_rate=hp["learning_rate"], n_steps=a.num_steps,
                batch_size=rollout // a.num_minibatches, n_epochs=hp["n_epochs"],
                gamma=hp["gamma"], gae_lambda=hp["gae_lambda"], clip_range=hp["clip_range"],
                normalize_advantage=hp["normalize_advantage"], ent_coef=hp["ent_coef"],
                vf_coef=hp["vf_coef"], max_grad_norm=hp["max_grad_norm"],
                target_kl=hp["target_kl"], seed=a.seed, device="cpu", verbose=0,
                policy_kwargs=dict(net_arch=dict(pi=[256, 256, 256], vf=[256, 256, 256]),
                                   activation_fn=torch.nn.Tanh, ortho_init=True,
                                   log_std_init=hp["log_std_init"]))
    setup_s = time.perf_counter() - t_setup
    curve: list[dict[str, Any]] = []
    clock = {"eval": 0.0, "start": 0.0}

    def point(steps: int, train_eps: int, train_ok: int) -> None:
        t0 = time.perf_counter()
        r = evaluate(model, eval_env, eval_seeds)
        clock["eval"] += time.perf_counter() - t0
        elapsed = time.perf_counter() - clock["start"]
        r.update(env_steps_trained=steps, wall_s=round(elapsed, 1),
                 training_wall_s=round(elapsed - clock["eval"], 1),
                 training_episodes=train_eps, training_successes=train_ok,
                 load=os.getloadavg()[0])
        curve.append(r)
        print(f"{steps:>9} steps  eval {r['successes']}/{r['episodes']}  training episodes "
              f"{train_ok}/{train_eps} ok  {elapsed:.0f} s  load {r['load']:.1f}", flush=True)

    class Curve(BaseCallback):
        def __init__(self) -> None:
            super().__init__()
            self.next = a.eval_every
            self.eps = self.ok = 0

        def _on_training_start(self) -> None:
            clock["start"] = time.perf_counter()
            point(0, 0, 0)

        def _on_step(self) -> bool:
            for done, info in zip(self.locals["dones"], self.locals["infos"]):
                if done:
                    self.eps += 1
                    self.ok += bool(info.get("success"))
            return True

        def _on_rollout_end(self) -> None:
            if self.num_timesteps >= self.next:
                point(self.num_timesteps, self.eps, self.ok)
                self.eps = self.ok = 0
                while self.next <= self.num_timesteps:
                    self.next += a.eval_every

        def _on_training_end(self) -> None:
            if curve[-1]["env_steps_trained"] < self.num_timesteps:
                point(self.num_timesteps, self.eps, self.ok)

    model.learn(total_timesteps=total, callback=Curve())
    wall = time.perf_counter() - clock["start"]
    train_wall = wall - clock["eval"]
    venv.close()
    eval_env.close()
    best = max(curve, key=lambda r: (r["success_rate"], -r["env_steps_trained"]))
    return {
        "what": ("stable-baselines3 PPO on ManiSkill's PullCubeTool-v1 (state observations, "
                 "CPU simulation), success of the deterministic policy on fresh seeds "
                 "against training environment steps"),
        "command": "bench/ppo_baseline_bench.py " + " ".join(sys.argv[1:]),
        "env_id": a.env_id, "budget_env_steps": a.budget, "env_steps_trained": total,
        "rollout_env_steps": rollout, "updates": iterations,
        "eval": {"every_env_steps": a.eval_every, "episodes": a.eval_episodes,
                 "seeds": [eval_seeds[0], eval_seeds[-1]],
                 "success": "ManiSkill's evaluate() success (info['success']) at the "
                            "episode's end; the episode ends on success or at 100 steps",
                 "policy": "deterministic (the Gaussian's mean)"},
        "training_seeds": {"first": TRAIN_SEED_BASE,
                           "rule": "environment i resets on base + i + k * num_envs",
                           "episodes_reset": sum(used),
                           "last": TRAIN_SEED_BASE + max(
                               i + (used[i] - 1) * a.num_envs
                               for i in range(a.num_envs) if used[i])},
        "ppo_seed": a.seed,
        "hyperparameters": hp,
        "hyperparameter_sources": {k: why for k, (_, why) in HYPERPARAMETERS.items()},
        "curve": curve,
        "final": curve[-1], "best": {k: best[k] for k in
                                     ("env_steps_trained", "successes", "episodes")},
        "wall_s": {"setup": round(setup_s, 1), "total": round(wall, 1),
                   "training": round(train_wall, 1), "evaluation": round(clock["eval"], 1)},
        "steps_per_s": {"training": round(total / train_wall, 1),
                        "one_env_random_actions": round(speed, 1)},
        "machine": {"cores": os.cpu_count(), "platform": platform.platform(),
                    "processor": platform.processor() or platform.machine(),
                    "torch_threads": torch.get_num_threads(),
                    "niceness": os.nice(0),
                    "uptime_before": load_before, "uptime_after": load(),
                    "shared": "2 cores shared with other engineers' work"},
        "versions": versions(),
    }


def plot(result: dict[str, Any], learner: dict[str, Any] | None, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 4.2), dpi=110)
    pts = [r for r in result["curve"] if r["env_steps_trained"] > 0]
    xs = [r["env_steps_trained"] for r in pts]
    ys = [100 * r["success_rate"] for r in pts]
    ev = result["eval"]
    first = result["curve"][0]
    ax.plot(xs, ys, "o-", color="tab:blue",
            label=(f"PPO (stable-baselines3): {ev['episodes']} fresh seeds "
                   f"{ev['seeds'][0]}-{ev['seeds'][1]} a point "
                   f"({first['successes']}/{first['episodes']} untrained)"))
    if learner is not None:
        lr = learner["learning"]
        ax.plot([lr["env_steps"]], [100 * learner["success_rate"]], "*", color="tab:red",
                markersize=16,
                label=(f"CREATIVE-py: 1 demonstration + {lr['trials']} trials "
                       f"({lr['env_steps']} steps);\nits model on {len(learner['seeds'])} fresh "
                       f"seeds {learner['seeds'][0]}-{learner['seeds'][-1]}: "
                       f"{learner['successes']}/{len(learner['seeds'])}"))
    ax.set_xscale("log")
    ax.set_xlim(100, max(xs + [1000]) * 1.5)
    ax.set_ylim(-3, 103)
    ax.set_xlabel("environment (control) steps used for learning")
    ax.set_ylabel("success on fresh ManiSkill seeds (%)")
    w = result["wall_s"]["training"]
    ax.set_title(f"{result['env_id']}: PPO trained {result['env_steps_trained']:,} steps "
                 f"({w / 60:.1f} min of training on a shared 2-core CPU)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="center right", fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    try:
        a = parse(argv)
        for module, dist in (("stable_baselines3", "stable-baselines3"),
                             ("mani_skill", "mani-skill")):
            try:
                __import__(module)
            except ImportError:
                raise Usage(f"{dist} is not installed: make bench-rl installs the rl and "
                            f"maniskill extras") from None
    except Usage as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    learner = json.loads(a.learner.read_text()) if a.learner else None
    if a.replot:
        try:
            result = json.loads(a.out.read_text())
            plot(result, learner, a.plot)
        except (ValueError, KeyError, TypeError) as e:
            print(f"error: --out: {a.out}: not a result of this benchmark ({e})",
                  file=sys.stderr)
            return 2
        print(a.plot)
        return 0
    os.environ.setdefault("VK_ICD_FILENAMES", "/usr/share/vulkan/icd.d/lvp_icd.json")
    result = train(a)
    if learner is not None:
        result["learner"] = {"source": str(a.learner.relative_to(HERE.parent))
                             if a.learner.is_relative_to(HERE.parent) else str(a.learner),
                             "env_steps": learner["learning"]["env_steps"],
                             "trials": learner["learning"]["trials"],
                             "successes": learner["successes"],
                             "seeds": [learner["seeds"][0], learner["seeds"][-1]]}
    a.out.parent.mkdir(parents=True, exist_ok=True)
    a.out.write_text(json.dumps(result, indent=1) + "\n")
    plot(result, learner, a.plot)
    f = result["final"]
    print(f"PPO after {result['env_steps_trained']:,} steps: {f['successes']}/{f['episodes']} "
          f"fresh seeds; {result['wall_s']['training']:.0f} s of training "
          f"({result['steps_per_s']['training']:.0f} steps/s); {a.out}, {a.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
