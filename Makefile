# CREATIVE-py: every target installs what it needs on a fresh Debian-like machine.
SHELL := /bin/bash
VENV  := .venv
PY    := $(VENV)/bin/python
SWIPL := swipl
STAMP := $(VENV)/.installed
SUDO  := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
comma := ,
RUN   ?=
SEED  ?= 0
CASE  ?= hook
OUT   ?= runs
# make hook/wedge/rake show tool creation even when a catalogued object solved the
# harder task first (creative run --demonstrate-creation); CREATE= turns that off.
CREATE ?= --demonstrate-creation
# make run BACKEND=ros: the case on the stand-in arm over ROS 2 (make setup-ros first);
# ROS_DOMAIN is the domain id of its private, loopback-only network namespace. PROFILE
# (or ROBOT) names the robot profile (robots/<name>.toml or a .toml path; default
# the case's robot); RESUME=DIR goes on with an interrupted or stopped run (over ROS its case,
# options and profile from DIR/run.json; otherwise give its CASE=).
BACKEND ?=
ROS_DOMAIN ?= 42
# make run ROBOT=panda: the case on another arm (a profile of robots/, docs/robots.md;
# default: the case's robot).
ROBOT ?=
PROFILE ?= $(ROBOT)
RESUME ?=

.PHONY: help setup setup-maniskill test-narrow test-maniskill bench-maniskill bench-maniskill-poke bench-robotoolbench setup-ros test-ros test test-prolog test-python test-all mutate-prolog run cases hook wedge rake repl bench readme-figures mutate clean bench-rl bench-ros

help:  ## List the targets.
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | expand -t 14

# System packages: the Prolog engine, OpenSCAD (the .scad check), PrusaSlicer (G-code of
# every printable piece), ffmpeg (video), Chromium (the HTML report's browser test),
# libsdformat with g++ and pkg-config (Gazebo's parser: the test of the Gazebo models).
APT_PACKAGES := swi-prolog-nox openscad prusa-slicer ffmpeg chromium libsdformat-dev g++ pkg-config
APT_PROGRAMS := swipl openscad prusa-slicer ffmpeg chromium g++ pkg-config

# Each long step says what it installs before it starts (`say`; with the time it took
# on a fresh clone on a 2-core machine where that was measured: issue 32) and how long
# it took when it ends (bash's `time`, in the format TIMEFORMAT gives).
say = @printf '\n==> %s\n' "$(1)"
export TIMEFORMAT := ==> took %0R s

/usr/bin/swipl:
	$(call say,apt: installing SWI-Prolog$(comma) OpenSCAD$(comma) PrusaSlicer$(comma) ffmpeg$(comma) Chromium$(comma) libsdformat and g++ (minutes: downloads))
	$(SUDO) apt-get update -qq
	DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $(APT_PACKAGES) >/dev/null

$(STAMP): pyproject.toml | /usr/bin/swipl
	@for p in $(APT_PROGRAMS); do command -v $$p >/dev/null || missing=1; done; \
	  pkg-config --exists sdformat12 2>/dev/null || missing=1; \
	  [ -z "$$missing" ] || (printf '\n==> %s\n' "apt: installing the missing system packages: $(APT_PACKAGES) (minutes: downloads)" && \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $(APT_PACKAGES) >/dev/null)
	$(call say,pip: creating $(VENV) and installing CREATIVE-py with pybullet$(comma) trimesh$(comma) manifold3d$(comma) pyswip$(comma) pytest and the rest of its test tools (about 75 s))
	python3 -m venv $(VENV)
	@# setuptools as pyproject.toml's build-system asks (a venv of Python 3.11 starts with
	@# 65.5, which rejects the licence expression license = "MIT").
	$(PY) -m pip install -q --upgrade pip 'setuptools>=77'
	time $(PY) -m pip install -q -e '.[test]'
	$(PY) -m pip install -q --no-deps example-robot-data
	touch $(STAMP)
	$(call say,setup done: $(VENV) is ready)

setup: $(STAMP)  ## Install SWI-Prolog, OpenSCAD, PrusaSlicer, ffmpeg, Chromium and the Python environment.

# The ManiSkill3 backend (optional): Mesa 25's Vulkan drivers from bookworm-backports
# (SAPIEN needs a Vulkan device even without rendering; Debian 12's Mesa 22 lavapipe lacks
# an extension it asks for), then the maniskill extra into the project's environment.
# Idempotent: the backports source is written once, pip skips what is installed.
BACKPORTS := /etc/apt/sources.list.d/bookworm-backports.sources
LAVAPIPE  := /usr/share/vulkan/icd.d/lvp_icd.json
MS_STAMP  := $(VENV)/.maniskill

$(BACKPORTS):
	printf 'Types: deb\nURIs: http://deb.debian.org/debian\nSuites: bookworm-backports\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' | $(SUDO) tee $@ >/dev/null

$(MS_STAMP): pyproject.toml $(STAMP) | $(BACKPORTS)
	@dpkg-query -W -f='$${Version}' mesa-vulkan-drivers 2>/dev/null | grep -q '^2[5-9]' || \
	  (printf '\n==> %s\n' "apt: installing Mesa 25's Vulkan drivers from bookworm-backports (a download)" && \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install \
	  -y -qq -t bookworm-backports mesa-vulkan-drivers libvulkan1 >/dev/null)
	$(call say,pip: installing torch 2.13.0 (the CPU build)$(comma) then mani-skill and SAPIEN (the maniskill extra): about 3.5 min for the two)
	time $(PY) -m pip install -q torch==2.13.0
	time $(PY) -m pip install -q -e '.[test,maniskill]'
	touch $(MS_STAMP)
	$(call say,setup-maniskill done: run the ManiSkill cases with VK_ICD_FILENAMES=$(LAVAPIPE))

setup-maniskill: $(MS_STAMP)  ## Install the ManiSkill3 backend (Mesa 25 Vulkan on the CPU, mani-skill, CPU torch).

test-maniskill: $(MS_STAMP)  ## Run the ManiSkill backend's tests (a real short episode each).
	VK_ICD_FILENAMES=$(LAVAPIPE) $(PY) -m pytest -q -p no:randomly -n 0 tests/python/backends/maniskill

# A learning run of the ManiSkill case, then its learned model on 20 fresh ManiSkill seeds
# (bench/results/maniskill.json) and the demonstration's tool and pose on the same seeds.
bench-maniskill: $(MS_STAMP)  ## Learn pull_cube_tool in ManiSkill and evaluate the model on 20 fresh seeds (about 4 min).
	run=$$($(VENV)/bin/creative run pull_cube_tool --seed 0 --out $(OUT) --video none | tail -1) && \
	  $(PY) bench/maniskill_bench.py pull_cube_tool --run $$run --record && \
	  $(PY) bench/maniskill_bench.py pull_cube_tool --out bench/results/maniskill_demonstration.json

# RoboToolBench's tasks (every case whose manifest names it), each run whole over 5
# drawn worlds beside the benchmark's published figures (bench/results/robotoolbench.json,
# docs/results.md).
bench-robotoolbench: $(STAMP)  ## Run RoboToolBench's tasks over 5 drawn worlds each beside its published figures.
	nice -n 5 $(PY) bench/robotoolbench.py --world-seeds 0-4 --record && $(PY) bench/readme_figures.py

# The second ManiSkill task: a learning run of poke_cube, then its learned model on 50
# fresh ManiSkill seeds (bench/results/maniskill_poke.json).
bench-maniskill-poke: $(MS_STAMP)  ## Learn poke_cube in ManiSkill and evaluate the model on 50 fresh seeds (about 3 min).
	run=$$($(VENV)/bin/creative run poke_cube --seed 0 --out $(OUT) --video none | tail -1) && \
	  $(PY) bench/maniskill_bench.py poke_cube --run $$run --seeds 1000:1050 \
	    --out bench/results/maniskill_poke.json

# The PPO baseline on ManiSkill's own PullCubeTool-v1 (state observations, CPU simulation,
# stable-baselines3 from the rl extra) for a fixed budget of environment steps: its success
# on 50 fresh seeds against steps, beside the learner's (bench/results/ppo_baseline.json and
# .png). Niced, one torch thread. STEPS=384000 took 48 min of training and 10 of evaluation
# on the shared 2-core machine at load 2-13 (picked at 350 steps/s, load 2.7, it ran at
# 133); give millions where there is time.
RL_STAMP := $(VENV)/.rl
STEPS    ?= 384000

$(RL_STAMP): pyproject.toml $(MS_STAMP)
	$(call say,pip: installing stable-baselines3 (the rl extra))
	time $(PY) -m pip install -q -e '.[test,maniskill,rl]'
	touch $(RL_STAMP)

bench-rl: $(RL_STAMP)  ## Train the PPO baseline on ManiSkill's PullCubeTool-v1 for STEPS steps (about an hour here) and record its success curve.
	VK_ICD_FILENAMES=$(LAVAPIPE) nice -n 10 $(PY) bench/ppo_baseline_bench.py --budget $(STEPS) --record

# The ROS 2 backend (optional; docs/real-robot.md): ROS 2 Kilted's rclpy, Fast DDS and the
# standard messages from PyPI wheels (the ros extra), then control_msgs' FollowJointTrajectory
# and GripperCommand (not a wheel) built once from ros/control_msgs/ with plain CMake and
# installed into the venv, where the wheels' .pth hook already finds its libraries. Three
# workarounds: the ros extra names the build wheels the ROS wheels forget to require,
# AMENT_PREFIX_PATH points at the venv during the build (typesupport discovery), and
# ros/control_msgs/CMakeLists.txt repoints the wheels' build-host include directories.
# Idempotent: the stamp is remade only when pyproject.toml or the interface files change.
ROS_STAMP := $(VENV)/.ros
ROS_BUILD := $(VENV)/build/control_msgs
ROS_IFACES := $(wildcard ros/control_msgs/*.txt ros/control_msgs/*.xml ros/control_msgs/msg/*.msg ros/control_msgs/action/*.action)

$(ROS_STAMP): pyproject.toml $(STAMP) $(ROS_IFACES)
	@command -v cmake >/dev/null && command -v g++ >/dev/null && command -v ip >/dev/null || \
	  ($(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq cmake g++ iproute2 >/dev/null)
	$(call say,pip: installing ROS 2 Kilted's rclpy$(comma) Fast DDS and the standard messages (the ros extra))
	time $(PY) -m pip install -q -e '.[test,ros]'
	$(call say,cmake: building control_msgs (FollowJointTrajectory$(comma) GripperCommand) into $(VENV) (about 3 min; its output goes to $(ROS_BUILD)/make.log$(comma) the end of which is shown if it fails))
	@mkdir -p $(ROS_BUILD)
	venv=$$(cd $(VENV) && pwd) && time { \
	  AMENT_PREFIX_PATH=$$venv cmake -S ros/control_msgs -B $(ROS_BUILD) -Wno-dev \
	    -DCMAKE_PREFIX_PATH=$$venv -DCMAKE_INSTALL_PREFIX=$$venv -DPython3_EXECUTABLE=$$venv/bin/python \
	    -DBUILD_TESTING=OFF -DCMAKE_BUILD_TYPE=Release && \
	  AMENT_PREFIX_PATH=$$venv cmake --build $(ROS_BUILD) -j2 && \
	  cmake --install $(ROS_BUILD); } >$(ROS_BUILD)/make.log 2>&1 || \
	  { tail -n 30 $(ROS_BUILD)/make.log; echo "control_msgs build failed: $(ROS_BUILD)/make.log"; exit 1; }
	$(PY) -c 'from control_msgs.action import FollowJointTrajectory, GripperCommand'
	touch $(ROS_STAMP)
	$(call say,setup-ros done: control_msgs built and importable)

setup-ros: $(ROS_STAMP)  ## Install the ROS 2 backend (rclpy wheels, control_msgs built once; 1-4 min).

# Each test runs its ROS traffic in a private network namespace with only loopback (it
# calls unshare itself and skips, saying why, where the namespace is refused).
test-ros: $(ROS_STAMP)  ## Run the ROS 2 backend's tests (the stand-in arm in its own process).
	$(PY) -m pytest -q -p no:randomly -n 0 tests/python/backends/ros

bench-ros: $(ROS_STAMP)  ## Measure the stand-in's rates and a goal's round trip, idle and under load.
	$(PY) bench/ros_roundtrip.py --record

test: test-prolog test-python  ## Run the quick test suite (Prolog plunit + pytest, sim tests included).

test-prolog: $(STAMP)  ## Run the plunit tests under --on-warning=status.
	$(SWIPL) --on-warning=status -q -g run_all -t halt tests/prolog/run_tests.pl

test-python: $(STAMP)  ## Run pytest without the slow tests, one worker a core.
	$(PY) -m pytest -q -m "not slow" -n auto

# The quick pytest suite once more with numpy's vector dispatch narrowed to its baseline
# (every dispatch target of this numpy disabled: NPY_DISABLE_CPU_FEATURES), standing in for
# another CPU: a test that pins a float numpy computed to its last bit fails here. The
# check before it refuses to run when the narrowing did not take (numpy ignores names it
# does not know). It leaves out what computes no float to compare: tests/reliability
# (exit codes, messages, locks, kills and resumes, each run compared with itself on the
# same machine), tests/python/architecture (scans of the source) and tests/python/bridge
# (the Prolog facade, which imports only the standard library, pyswip and itself:
# test_imports.py checks it). The folders are named, not --ignore'd: pytest does not
# ignore a folder that testpaths names.
NUMPY_DISPATCH := from numpy._core import _multiarray_umath as m
test-narrow: $(STAMP)  ## Run pytest again with numpy's vector dispatch narrowed to its baseline (another CPU).
	@features=$$($(PY) -c '$(NUMPY_DISPATCH); print(" ".join(m.__cpu_dispatch__))') && \
	  export NPY_DISABLE_CPU_FEATURES="$$features" && \
	  $(PY) -c '$(NUMPY_DISPATCH); on = [f for f in m.__cpu_dispatch__ if m.__cpu_features__.get(f)]; \
	    assert not on, f"numpy still dispatches to {on}"; \
	    print("numpy narrowed to its baseline", m.__cpu_baseline__, "(disabled:", " ".join(m.__cpu_dispatch__) + ")")' && \
	  $(PY) -m pytest -q -m "not slow" -n auto tests/python tests/integration --ignore=tests/python/architecture \
	    --ignore=tests/python/bridge

test-all: test-prolog $(STAMP)  ## Run every test, the slow learning runs included.
	$(PY) -m pytest -q -n auto

mutate-prolog: $(STAMP)  ## Run the hand-written mutants of the Prolog core; score in bench/results/prolog_mutants.json.
	$(PY) tests/prolog/mutants/mutants.py

run: $(STAMP) $(if $(filter ros,$(BACKEND)),$(ROS_STAMP))  ## Any case end to end (CASE=<id>, see make cases; ROBOT=<profile>: another arm; BACKEND=ros: over ROS 2; RESUME=DIR: go on with a run).
ifeq ($(BACKEND),ros)
	@# The stand-in and the learner, two processes talking ROS 2 in a private network
	@# namespace with only loopback (unshare -n where allowed, else -rn). The learner's
	@# Ctrl-C hint names this target (CREATIVE_RESUME_COMMAND).
	@prefix="unshare -n"; $$prefix true 2>/dev/null || prefix="unshare -rn"; \
	$$prefix sh -c 'ip link set lo up && ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST \
	  ROS_DOMAIN_ID=$(ROS_DOMAIN) \
	  CREATIVE_RESUME_COMMAND="make run BACKEND=ros$(if $(filter-out .venv,$(VENV)), VENV=$(VENV)) RESUME={run}" \
	  exec $(PY) -m creative_py.backends.ros.launch $(if $(PROFILE),--profile $(PROFILE)) \
	  $(if $(RESUME),--resume $(RESUME),--case $(CASE) -- run $(CASE) --seed $(SEED) \
	  --out $(OUT) $(CREATE) --backend ros)'
else ifneq ($(RESUME),)
	$(VENV)/bin/creative run $(CASE) --resume $(RESUME)
else
	$(VENV)/bin/creative run $(CASE) --seed $(SEED) --out $(OUT) $(CREATE) \
	  $(if $(BACKEND),--backend $(BACKEND)) $(if $(ROBOT),--robot $(ROBOT))
endif

cases: $(STAMP)  ## List the cases (every worlds/*/case.toml).
	$(VENV)/bin/creative cases

hook: $(STAMP)  ## Case 1 end to end: demonstration, tool-use learning, hook creation.
	$(MAKE) --no-print-directory run CASE=hook

wedge: $(STAMP)  ## Case 2 end to end: demonstration, tool-use learning, wedge creation.
	$(MAKE) --no-print-directory run CASE=wedge

rake: $(STAMP)  ## Case 3 end to end: a rake pulls a box from under a shelf, rake creation.
	$(MAKE) --no-print-directory run CASE=rake

repl: $(STAMP)  ## Prolog REPL with the engine loaded (RUN=<run folder> loads its model.pl).
	$(VENV)/bin/creative repl $(RUN)

bench: $(STAMP)  ## Run the benchmarks (about 40 min) and record their figures in bench/results/.
	$(PY) bench/run_all.py

readme-figures: $(STAMP)  ## Write the README's figures and docs/results.md (from docs/results.md.in) from bench/results/.
	$(PY) bench/readme_figures.py

# MUTATE_ARGS narrows the run, e.g. MUTATE_ARGS="--only creative_py/report/table.py".
MUTATE_ARGS ?=
mutate: $(STAMP)  ## Mutation testing of learning/, case.py, report/ (hours); score in bench/results/mutation.json.
	$(call say,pip: installing mutmut (the mutate extra))
	time $(PY) -m pip install -q -e '.[mutate]'
	$(PY) bench/mutation.py --record $(MUTATE_ARGS)

clean:  ## Remove the environment and run folders.
	rm -rf $(VENV) runs .pytest_cache mutants
