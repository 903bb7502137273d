"""Studies: the same numbers as the CLI, poses against sigma, shards."""

import json
import math
import re
import warnings

import numpy as np
import pytest

import kinrepro

DOFS = ["x_nm", "y_nm", "z_nm", "phi_x_nrad", "phi_y_nrad", "phi_z_nrad"]

# The library's parameters as Python spells them (`samples=7`); the CLI
# spells the same parameters as flags (`--samples 7`).
KEYWORDS = [
    "samples", "sampler", "seed", "shard", "solver", "increments", "path_tolerance", "vary",
    "offset_bounds", "tilt_bounds", "sensitivity", "sobol_samples", "replicates", "mu", "jobs",
]


def test_version_and_error_type():
    assert kinrepro.__version__.count(".") == 2
    assert issubclass(kinrepro.KinreproError, ValueError)


def test_study_json_carries_the_cli_sigma(study01, cli):
    ours = json.loads(study01.to_json())
    theirs = cli(
        "study", "scenes/01_maxwell_vgroove_steel.toml",
        "--sampler", "mc", "--samples", 400, "--seed", 9, "--format", "json",
    )
    assert len(ours["variants"]) == len(theirs["variants"]) == 1
    for a, b in zip(ours["variants"][0]["points"], theirs["variants"][0]["points"]):
        assert a["name"] == b["name"]
        for k in DOFS:
            assert a["sigma"][k] == pytest.approx(b["sigma"][k], rel=1e-12, abs=0)
    # The whole document is the CLI's (same file name, same options).
    assert ours == theirs


def test_poses_std_equals_sigma(study01):
    poses = study01.poses("centre")
    assert poses.shape == (400, 6)
    assert poses.dtype == np.float64
    sigma = study01.sigma("centre")
    assert isinstance(sigma, np.ndarray) and sigma.shape == (6,)
    std = poses.std(axis=0, ddof=1)
    for j, k in enumerate(DOFS):
        assert std[j] == pytest.approx(sigma[j], rel=1e-9), k
    # The JSON's sigma (nm, nrad) is the same number.
    for j, k in enumerate(DOFS):
        assert study01.stats("centre")["sigma"][k] == pytest.approx(sigma[j] * 1e9, rel=1e-12), k
    # The scatter is friction-induced: nm scale, not zero, not metres.
    assert 1e-12 < sigma[0] < 1e-5


def test_sigma_is_one_convention_and_the_old_keys_are_deprecated(study01, scene01):
    # Study, Sweep and Prediction give sigma as arrays in m and rad.
    s = study01.sigma("centre")
    sweep = kinrepro.sweep(scene01, sets={"preload.force": [20.0]}, samples=400, sampler="mc", seed=9)
    np.testing.assert_array_equal(sweep.sigma("centre")[0], s)
    # The old dict spelling of Study.sigma() still answers, in nm, with a warning.
    with pytest.warns(DeprecationWarning, match="SI"):
        assert s["x_nm"] == pytest.approx(s[0] * 1e9, rel=1e-15)
    with pytest.warns(DeprecationWarning):
        assert s.keys() == DOFS
    with pytest.warns(DeprecationWarning):
        assert dict(s.items())["phi_z_nrad"] == pytest.approx(s[5] * 1e9, rel=1e-15)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert float(s[1]) == s.tolist()[1]  # indexing by number warns of nothing


def test_inputs_are_the_sampled_friction(study01, scene01):
    names = study01.input_names()
    x = study01.inputs()
    assert names == [f"mu_{k + 1}" for k in range(x.shape[1])]
    assert x.shape == (400, 6)
    # mu_s uniform in mu0 +- spread (scene 01: 0.5 +- 0.05).
    assert x.min() >= 0.45 and x.max() <= 0.55
    assert abs(x.mean() - 0.5) < 0.005
    assert study01.indices() == list(range(400))


def test_from_json_round_trips(study01):
    text = study01.to_json()
    again = kinrepro.Study.from_json(text)
    assert again == study01
    assert again.to_json() == text
    # Saved by an editor that writes a byte-order mark: the same document.
    assert kinrepro.Study.from_json("\ufeff" + text) == study01
    # A statistic its records contradict is refused, naming it.
    doc = json.loads(text)
    doc["variants"][0]["points"][0]["sigma"]["x_nm"] = 1e6
    with pytest.raises(kinrepro.KinreproError, match=r"sigma\.x_nm: 1000000 disagrees with the records"):
        kinrepro.Study.from_json(json.dumps(doc))
    with pytest.raises(kinrepro.KinreproError, match="not a kinrepro study JSON"):
        kinrepro.Study.from_json("{}")


def test_four_shards_merge_to_one_run(study01, scene01):
    parts = [
        kinrepro.study(scene01, samples=400, sampler="mc", seed=9, shard=f"{i}/4")
        for i in (3, 1, 4, 2)
    ]
    assert [p.shard for p in parts] == [(3, 4), (1, 4), (4, 4), (2, 4)]
    with pytest.raises(kinrepro.KinreproError, match="shard"):
        parts[0].sigma()
    merged = kinrepro.merge(parts)
    np.testing.assert_array_equal(merged.sigma("centre"), study01.sigma("centre"))
    np.testing.assert_array_equal(merged.poses(), study01.poses())
    # Through JSON text, as files would travel.
    np.testing.assert_array_equal(
        kinrepro.merge([p.to_json() for p in parts]).sigma(), study01.sigma()
    )


def test_preload_scales_sigma_z_by_the_hertz_power(scene01):
    # Scene 01 slides at every contact: the pose is F^(2/3) times a
    # friction-only pattern, so sigma_z scales by (F2/F1)^(2/3) exactly.
    base = kinrepro.study(scene01, samples=50, sampler="mc", seed=3)
    heavy = kinrepro.study(scene01.set("preload.force", 40.0), samples=50, sampler="mc", seed=3)
    ratio = heavy.sigma()[2] / base.sigma()[2]
    assert ratio == pytest.approx((40.0 / 20.0) ** (2.0 / 3.0), rel=1e-6)


def test_scene_set_and_toml(scene01):
    s = scene01.set("friction.mu_static", 0.3)
    assert "mu_static = 0.3" in s.to_toml()
    assert kinrepro.Scene.from_toml(s.to_toml()).name == scene01.name
    assert scene01.to_toml() != s.to_toml()  # the original is unchanged
    with pytest.raises(kinrepro.KinreproError, match="preload.bogus"):
        scene01.set("preload.bogus", 1.0)
    # True is 1 to Python, not a force: refused, as a string would be.
    with pytest.raises(kinrepro.KinreproError, match="preload.force: needs a number, got True"):
        scene01.set("preload.force", True)
    # No scene, no study (not an empty one).
    with pytest.raises(kinrepro.KinreproError, match="empty list"):
        kinrepro.study([])
    # A value the scene refuses names the set, not a line of a file the
    # user never wrote (the set scene is new text).
    with pytest.raises(kinrepro.KinreproError) as e:
        scene01.set("preload.force", -5)
    msg = str(e.value)
    assert 'after set("preload.force", -5)' in msg and "must be positive" in msg, msg
    assert re.search(r"\.toml:\d", msg) is None, msg


def test_bad_scene_raises_the_library_message(tmp_path):
    bad = tmp_path / "bad.toml"
    text = (kinrepro.Scene.load("scenes/01_maxwell_vgroove_steel.toml").to_toml()
            .replace("force = 20.0", "force = -5.0"))
    bad.write_text(text)
    with pytest.raises(kinrepro.KinreproError) as e:
        kinrepro.Scene.load(bad)
    msg = str(e.value)
    assert msg.startswith(f"{bad}:") and "preload.force" in msg
    # The CLI prints the same line: `error: <message>`.
    from conftest import cli_path
    import subprocess
    if cli_path().is_file():
        r = subprocess.run([str(cli_path()), "check", str(bad)], capture_output=True, text=True)
        assert r.returncode != 0
        assert f"error: {msg}" in r.stderr.splitlines()
    with pytest.raises(ValueError):
        kinrepro.Scene.from_toml("not toml [")
    with pytest.raises(kinrepro.KinreproError, match="cannot read"):
        kinrepro.Scene.load(tmp_path / "missing.toml")


def test_bad_options_raise(scene01):
    with pytest.raises(kinrepro.KinreproError, match="sampler"):
        kinrepro.study(scene01, sampler="sobolish")
    with pytest.raises(kinrepro.KinreproError, match="vary"):
        kinrepro.study(scene01, vary=("wind",))
    with pytest.raises(kinrepro.KinreproError, match="shard"):
        kinrepro.study(scene01, shard="5/4")
    with pytest.raises(kinrepro.KinreproError, match="jobs"):
        kinrepro.study(scene01, jobs=0)
    with pytest.raises(kinrepro.KinreproError, match="lanes=sometimes: unknown, need auto, on or off"):
        kinrepro.study(scene01, lanes="sometimes")


def test_lanes_change_no_result(scene01):
    # Four seatings at a time in SIMD lanes, or one at a time: the same
    # records bit for bit (22 samples: five sets of four and two alone).
    runs = [kinrepro.study(scene01, samples=22, sampler="mc", lanes=l, jobs=j)
            for l, j in [("off", 1), ("on", 2), ("auto", 1)]]
    assert runs[1].to_json() == runs[0].to_json()
    assert runs[2].to_json() == runs[0].to_json()


def test_scene_defaults_and_jobs(scene01, cli):
    # No options: the scene's [study] settings (25 LHS samples, seed 1),
    # as `kinrepro study` without flags; the thread count changes nothing.
    s = kinrepro.study(scene01, jobs=1)
    theirs = cli("study", "scenes/01_maxwell_vgroove_steel.toml", "--format", "json")
    assert json.loads(s.to_json()) == theirs
    assert s.poses().shape == (25, 6)


def test_pickle_round_trip(scene01, study01):
    import pickle

    assert pickle.loads(pickle.dumps(scene01)) == scene01
    assert pickle.loads(pickle.dumps(study01)) == study01


def test_several_scenes_are_the_cli_study_of_several(cli):
    files = ["scenes/01_maxwell_vgroove_steel.toml", "scenes/02_maxwell_pins_steel.toml"]
    s = kinrepro.study([kinrepro.Scene.load(f) for f in files], samples=10, seed=2)
    assert len(s) == 2
    theirs = cli("study", *files, "--samples", 10, "--seed", 2, "--format", "json")
    assert json.loads(s.to_json()) == theirs
    assert s.stats(variant=1)["sigma"] == theirs["variants"][1]["points"][0]["sigma"]
    assert "samples=10" in repr(s) and '"lhs"' in repr(s)


OPTION_ERRORS = [
    (dict(vary=("friction", "start"), solver="dynamic"), ["--vary", "friction,start", "--solver", "dynamic"]),
    (dict(offset_bounds=(0, 0, 1e-6)), ["--offset-bounds", "0,0,1e-6"]),
    (dict(vary=("start",), solver="dynamic", tilt_bounds=(-1e-3, 0, 0)),
     ["--vary", "start", "--solver", "dynamic", "--tilt-bounds=-1e-3,0,0"]),
    (dict(sampler="corners", samples=10), ["--sampler", "corners", "--samples", 10]),
    (dict(solver="dynamic", increments=5), ["--solver", "dynamic", "--increments", 5]),
    (dict(increments=0), ["--increments", 0]),
    (dict(increments=40, path_tolerance=1e-6), ["--increments", 40, "--path-tolerance", 1e-6]),
    (dict(path_tolerance=0.5), ["--path-tolerance", 0.5]),
    (dict(solver="dynamic", path_tolerance=1e-6), ["--solver", "dynamic", "--path-tolerance", 1e-6]),
    (dict(sensitivity=True, sobol_samples=1), ["--sensitivity", "--sobol-samples", 1]),
    (dict(sensitivity=True, samples=200_000, sampler="mc"),
     ["--sensitivity", "--samples", 200_000, "--sampler", "mc"]),
    (dict(vary=("preload",)), ["--vary", "preload"]),
    (dict(jobs=0), ["--jobs", 0]),
]


def unspelled(message):
    """A message without its parameters' spellings: the CLI's flags
    (`--path-tolerance`), Python's `name=` and bare names, whitespace
    collapsed; what the one library check said, whoever asked."""
    for name in sorted(KEYWORDS, key=len, reverse=True):
        message = message.replace("--" + name.replace("_", "-"), " ")
        message = re.sub(rf"\b{name}=", " ", message)
        message = re.sub(rf"\b{name}\b", " ", message)
    return " ".join(message.split())


@pytest.mark.parametrize("kwargs, flags", OPTION_ERRORS, ids=[str(k) for k, _ in OPTION_ERRORS])
def test_option_errors_are_the_clis(scene01, kwargs, flags):
    # One library check refuses the options of both (the study plan): the
    # same message, each naming the parameter its own way: Python its
    # keyword, never a flag.
    from conftest import cli_path
    import subprocess

    with pytest.raises(kinrepro.KinreproError) as e:
        kinrepro.study(scene01, **kwargs)
    ours = str(e.value)
    assert "--" not in ours, ours
    assert any(k in ours for k in kwargs), ours
    if not cli_path().is_file():
        pytest.skip("the kinrepro CLI is not built")
    r = subprocess.run([str(cli_path()), "study", "scenes/01_maxwell_vgroove_steel.toml",
                        *map(str, flags)], capture_output=True, text=True)
    assert r.returncode != 0
    theirs = r.stderr.splitlines()[-1].removeprefix("error: ")
    assert "--" in theirs, theirs
    assert unspelled(theirs) == unspelled(ours)


@pytest.mark.parametrize("call, keyword", [
    (lambda s: kinrepro.study(s, path_tolerance=-1), "path_tolerance=-1"),
    (lambda s: kinrepro.study(s, samples=7), "samples=6"),
    (lambda s: kinrepro.seat(s, mu=[0.1] * 5), "mu needs 6 values"),
])
def test_messages_name_the_python_parameter(scene01, call, keyword):
    with pytest.raises(kinrepro.KinreproError) as e:
        call(scene01)
    assert keyword in str(e.value) and "--" not in str(e.value), str(e.value)


@pytest.mark.parametrize("kwargs, says", [
    (dict(samples=-1), "argument 'samples': -1 is negative"),
    (dict(seed=-3), "argument 'seed': -3 is negative"),
    (dict(samples=2.5), "argument 'samples': expected a whole number"),
    (dict(jobs=True), "argument 'jobs': expected a whole number >= 0, got a bool"),
    (dict(sobol_samples=10**30, sensitivity=True), "argument 'sobol_samples': "),
])
def test_bad_whole_numbers_name_the_argument(scene01, kwargs, says):
    # pyo3's own conversion raised a bare OverflowError naming nothing.
    with pytest.raises(TypeError) as e:
        kinrepro.study(scene01, **kwargs)
    assert says in str(e.value), str(e.value)


def test_a_sweep_with_no_valid_point_raises_as_the_cli_exits_1(scene01):
    # Grooves of 170 and 175 degrees cannot seat at mu 0.5:
    # the CLI exits 1; Python raised nothing and returned NaN rows.
    with pytest.raises(kinrepro.KinreproError, match="none of the 2 design points"):
        kinrepro.sweep(scene01, {"coupling.opening_angle_deg": [170, 175]}, samples=4)


def test_dynamic_start_study_is_the_clis(scene01, cli):
    # The options of the dynamic solver with a varied start pose, through
    # the same request: the same document.
    s = kinrepro.study(scene01, samples=4, sampler="mc", seed=2, vary=("friction", "start"),
                       solver="dynamic", offset_bounds=(1e-5, 1e-5, 2e-5), tilt_bounds=(1e-3, 1e-3, 0))
    theirs = cli("study", "scenes/01_maxwell_vgroove_steel.toml", "--samples", 4, "--sampler", "mc",
                 "--seed", 2, "--vary", "friction,start", "--solver", "dynamic",
                 "--offset-bounds", "1e-5,1e-5,2e-5", "--tilt-bounds", "1e-3,1e-3,0", "--format", "json")
    assert json.loads(s.to_json()) == theirs


def test_a_direction_is_the_projection_of_the_poses():
    own = 'directions = [{ name = "ion beam", vector = [0.788, 0.0, 0.616] }]'
    text = open("scenes/example_stage_mount.toml").read()
    assert own in text
    text = text.replace(own, 'directions = [{ name = "beam", vector = [1.0, 0.0, 1.0] }]\n'
                        'frame = { name = "tool", z = [0.0, 0.0, 1.0], x = [1.0, 1.0, 0.0] }\n')
    scene = kinrepro.Scene.from_toml(text, "stage.toml")
    s = kinrepro.study(scene, samples=30, sampler="mc", seed=4)
    poses = s.poses("sample")
    beam = s.along("beam")
    u = np.array([1.0, 0.0, 1.0]) / math.sqrt(2.0)
    np.testing.assert_allclose(beam, poses[:, :3] @ u, rtol=1e-12, atol=0)
    d = {x["kind"] + " " + x["name"]: x for x in s.stats("sample")["directions"]}
    assert d["along beam"]["sigma"] == pytest.approx(beam.std(ddof=1) * 1e9, rel=1e-12)
    assert d["along beam"]["unit"] == "nm"
    # The frame's rotation about its z is phi_z.
    np.testing.assert_allclose(s.about("tool.z"), poses[:, 5], rtol=1e-12, atol=0)
    with pytest.raises(kinrepro.KinreproError, match='along "nope": no such direction'):
        s.along("nope")


def test_optimize_is_the_clis_and_its_optimum_meets_the_bound(scene01, cli):
    o = kinrepro.optimize(
        scene01, {"preload.force": (5, 40)}, "preload.force:max",
        constraints=["sigma:centre:x<=6e-9"], samples=20, sampler="mc", seed=1,
    )
    theirs = cli(
        "optimize", "scenes/01_maxwell_vgroove_steel.toml", "--vary", "preload.force=5:40",
        "--objective", "preload.force:max", "--constraint", "sigma:centre:x<=6e-9",
        "--samples", 20, "--sampler", "mc", "--seed", 1, "--json",
    )
    ours = o.to_dict()
    assert ours["optimum"]["fields"] == theirs["optimum"]["fields"]
    assert o.optimum["constraint_margins"][0]["margin"] >= 0
    sigma_x = o.optimum["design"]["points"][0]["sigma"]["x_nm"]
    assert sigma_x <= 6.0 + 1e-9
    s = kinrepro.sweep(
        scene01, {"preload.force": [10, 20, 40]}, samples=10,
        objectives=["sigma:centre:x:min", "k_min:max"], constraints=["sf_p>=5"],
    )
    designs = s.to_dict()["designs"]
    assert [d["pareto"] for d in designs][2] is False
    assert designs[2]["broken_constraints"] == ["sf_p>=5"]
    with pytest.raises(kinrepro.KinreproError, match="not among those varied"):
        kinrepro.optimize(scene01, {"preload.force": (5, 40)}, "coupling.diameter:max")
