"""Scenario files: the schema, defaults, overrides, and every bad input refused with one sentence naming key and line."""

import math
import textwrap

import pytest

from rodparadox.errors import RodParadoxError, ScenarioError
from rodparadox.io.scenario import Particle, Scenario, Timing, builtin_names, configs_folder, load, parse


def refused(text: str) -> str:
    with pytest.raises(ScenarioError) as info:
        parse(textwrap.dedent(text), "s.yaml", "s")
    return str(info.value)


GOOD = """\
v: 0.6
particles:
  A: {gap: 0.5}
"""


def test_minimal_scenario_takes_the_documented_defaults():
    s = parse(GOOD, "s.yaml", "s")
    assert (s.name, s.v, s.L, s.description) == ("s", 0.6, 1.0, "")
    (a,) = s.particles
    assert (a.name, a.mass, a.gap, a.timed_with, a.end) == ("A", 1.0, 0.5, None, "left")
    assert s.speed(a) == 0.6  # a particle without a speed moves at v


def test_every_key_is_read():
    s = parse(textwrap.dedent("""\
        name: mine
        description: a test
        v: 0.3
        L: 2.5
        particles:
          B: {mass: 2, speed: 0.4, gap: 1.5}
          A: {mass: 0.5, timed_with: {particle: B, frame: 0.2, delay: 0.1}}
        """), "s.yaml", "s")
    assert (s.name, s.description, s.v, s.L) == ("mine", "a test", 0.3, 2.5)
    assert s.particle("B") == Particle("B", mass=2.0, speed=0.4, gap=1.5)
    assert s.particle("A").timed_with == Timing("B", 0.2, 0.1)
    assert s.frame_velocity("rest") == 0.0 and s.frame_velocity("moving") == -0.3 and s.frame_velocity(0.2) == 0.2


def test_builtin_scenarios_include_the_paper_and_three_more():
    names = builtin_names()
    assert {"fig1", "fig2"} <= set(names) and len(names) >= 5
    for name in names:
        assert load(name).name == name


def test_fig2_places_a_by_its_timing_not_by_a_typed_position():
    a = load("fig2").particle("A")
    assert a.gap is None and a.timed_with == Timing("B", "moving", 0.0)


def test_a_path_and_a_builtin_name_give_the_same_scenario(tmp_path):
    from rodparadox.io.scenario import configs_folder

    copy = tmp_path / "copy.yaml"
    copy.write_text((configs_folder() / "fig2.yaml").read_text())
    assert load(str(copy)) == load("fig2")


def test_overrides_replace_v_and_L_and_keep_the_rest():
    s = load("fig1").with_overrides(v=0.8, L=3.0)
    assert (s.v, s.L) == (0.8, 3.0) and s.particles == load("fig1").particles


@pytest.mark.parametrize("option, value, message", [
    ("v", 1.0, "v must be a number with 0 < v < 1 (units of c), got 1."),
    ("v", 0.0, "v must be a number with 0 < v < 1 (units of c), got 0."),
    ("v", -0.5, "v must be a number with 0 < v < 1 (units of c), got -0.5."),
    ("v", math.nan, "v must be a number with 0 < v < 1 (units of c), got nan."),
    ("v", 1e-9, "v must be between 1e-06 and 0.9999999 for double precision to place the impacts, got 1e-09."),
    ("v", 0.99999999, "v must be between 1e-06 and 0.9999999 for double precision to place the impacts, "
                      "got 0.99999999."),
    ("L", 0.0, "L must be a positive length (the rod's proper length), got 0."),
    ("L", math.inf, "L must be a positive length (the rod's proper length), got inf."),
])
def test_bad_overrides_name_their_key(option, value, message):
    """The key and the library's sentence; the command line names the option (test_cli)."""
    with pytest.raises(ScenarioError) as info:
        load("fig1").with_overrides(**{option: value})
    assert str(info.value) == message and info.value.key == option


@pytest.mark.parametrize("text, message", [
    ("v: 0.6\nparticles:\n  A: {gap: 0.5, spead: 0.3}\n",
     "s.yaml, line 3: unknown key 'spead' in particles.A (allowed: mass, speed, gap, timed_with); did you mean speed?"),
    ("v: 0.6\nparticle:\n  A: {gap: 0.5}\n",
     "s.yaml, line 2: unknown key 'particle' in the top level (allowed: name, description, title, v, L, rod, sound_speed, particles, forces); "
     "did you mean particles?"),
    ("v: 0.6\nparticles:\n  C: {gap: 0.5}\n",
     "s.yaml, line 3: unknown key 'C' in particles (allowed: A, B)."),
    ("v: 0.6\nv: 0.7\nparticles:\n  A: {gap: 0.5}\n",
     "s.yaml, line 2: v is given twice (first on line 1); keep one."),
    ("v: 0.6\nparticles:\n  A: {gap: 0.5}\n  A: {gap: 0.6}\n",
     "s.yaml, line 4: particles.A is given twice (first on line 3); keep one."),
    ('v: "fast"\nparticles:\n  A: {gap: 0.5}\n',
     "s.yaml, line 1: v must be a number with 0 < v < 1 (units of c), got 'fast'."),
    ("v: yes\nparticles:\n  A: {gap: 0.5}\n",
     "s.yaml, line 1: v must be a number with 0 < v < 1 (units of c), got yes/true (a boolean)."),
    ("v: 1\nparticles:\n  A: {gap: 0.5}\n",
     "s.yaml, line 1: v must be a number with 0 < v < 1 (units of c), got 1."),
    ("v: -1.5\nparticles:\n  A: {gap: 0.5}\n",
     "s.yaml, line 1: v must be a number with 0 < v < 1 (units of c), got -1.5."),
    ("v: 0\nparticles:\n  A: {gap: 0.5}\n",
     "s.yaml, line 1: v must be a number with 0 < v < 1 (units of c), got 0."),
    ("v: .nan\nparticles:\n  A: {gap: 0.5}\n",
     "s.yaml, line 1: v must be a number with 0 < v < 1 (units of c), got nan."),
    ("v: 0.5\nL: -1\nparticles:\n  A: {gap: 0.5}\n",
     "s.yaml, line 2: L must be a positive length (the rod's proper length), got -1."),
    ("v: 0.5\nL: .inf\nparticles:\n  A: {gap: 0.5}\n",
     "s.yaml, line 2: L must be a positive length (the rod's proper length), got inf."),
    ("v: 0.5\nparticles:\n  A: {gap: 0.5, speed: 0}\n",
     "s.yaml, line 3: particles.A.speed must be a number with 0 < speed < 1 (towards the rod, units of c), got 0; "
     "a particle that is at rest or moves away never reaches the rod."),
    ("v: 0.5\nparticles:\n  B:\n    gap: 0.5\n    speed: -0.2\n",
     "s.yaml, line 5: particles.B.speed must be a number with 0 < speed < 1 (towards the rod, units of c), got -0.2; "
     "a particle that is at rest or moves away never reaches the rod."),
    ("v: 0.5\nparticles:\n  A: {gap: -0.2}\n",
     "s.yaml, line 3: particles.A.gap must be a number >= 0 (distance from its end of the rod at t = 0, units of L), "
     "got -0.2; a negative gap puts the particle inside the rod."),
    ("v: 0.5\nparticles:\n  A: {gap: 0.5, speed: 0.0000001}\n",
     "s.yaml, line 3: particles.A.speed must be between 1e-06 and 0.9999999 for double precision to place the "
     "impacts, got 1e-07."),
    ("v: 0.5\nparticles:\n  A: {gap: 0.5, mass: 0}\n",
     "s.yaml, line 3: particles.A.mass must be a positive number (units of the rod's mass M), got 0."),
    ("v: 0.5\nparticles:\n  A: {speed: 0.5}\n",
     "s.yaml, line 3: particles.A needs exactly one of gap (its distance from the rod at t = 0) or timed_with "
     "(its impact timed against the other particle's)."),
    ("v: 0.5\nparticles:\n  A: {timed_with: {particle: B}}\n",
     "s.yaml, line 3: particles.A.timed_with.particle is B, but the scenario has no particle B."),
    ("v: 0.5\nparticles:\n  A: {timed_with: {particle: A}}\n  B: {gap: 1}\n",
     "s.yaml, line 3: particles.A.timed_with.particle must name the other particle, not A itself."),
    ("v: 0.5\nparticles:\n  A: {timed_with: {particle: B}}\n  B: {timed_with: {particle: A}}\n",
     "s.yaml, line 3: particles.A.timed_with.particle: A and B cannot both be timed against each other; give B a gap."),
    ("v: 0.5\nparticles:\n  A: {timed_with: {particle: B, frame: lab}}\n  B: {gap: 1}\n",
     "s.yaml, line 3: particles.A.timed_with.frame must be rest, moving or a velocity u with -0.9999999 <= u <= 0.9999999, got 'lab'."),
    ("v: 0.5\nparticles:\n  A: {timed_with: {frame: rest}}\n  B: {gap: 1}\n",
     "s.yaml, line 3: particles.A.timed_with needs the key particle (the other particle, A or B)."),
    ("v: 0.5\nparticles: {}\n", "s.yaml, line 2: particles must name at least one of A and B."),
    ("v: 0.5\n", "s.yaml: the scenario needs the key particles (a rod struck by particles) or forces (a rod driven by forces at its ends)."),
    ("v: 0.5\nparticles: [A, B]\n",
     "s.yaml, line 2: particles must be a mapping of keys (A, B), got a list."),
    ("- 1\n- 2\n", "s.yaml: the scenario must be a mapping of keys (name, description, title, v, L, rod, sound_speed, particles, forces), got a list."),
    ("", "s.yaml: the file is empty; a scenario needs at least v and particles."),
    ("v: 0.5\nparticles:\n  A: {gap: 0.5\n  B: x\n", "s.yaml, line 4: YAML syntax error: expected ',' or '}', but got ':'."),
    ("v: 0.5\nname: 12\nparticles:\n  A: {gap: 0.5}\n", "s.yaml, line 2: name must be text, got 12."),
])
def test_bad_scenarios_are_refused_with_one_sentence(text, message):
    assert refused(text) == message


def test_scenario_errors_are_value_errors_of_the_project():
    assert issubclass(ScenarioError, ValueError) and issubclass(ScenarioError, RodParadoxError)


def test_missing_file_and_unknown_name(tmp_path):
    with pytest.raises(ScenarioError, match=r"^scenario file '.*nope.yaml' does not exist; check the path"):
        load(str(tmp_path / "nope.yaml"))
    with pytest.raises(ScenarioError, match=r"^there is no built-in scenario 'fig9' and no file of that name; "
                                            r"built-in: fig1, fig2, "):
        load("fig9")
    with pytest.raises(ScenarioError, match=r"is a folder; give a .yaml file\.$"):
        load(str(tmp_path) + "/")


def test_not_utf8(tmp_path):
    bad = tmp_path / "latin.yaml"
    bad.write_bytes(b"v: 0.5 # \xe9\n")
    with pytest.raises(ScenarioError, match=r"is not UTF-8 text\.$"):
        load(str(bad))


def test_frozen():
    s = Scenario("x", 0.5, (Particle("A", gap=0.1),))
    with pytest.raises(AttributeError):
        s.v = 0.7


def test_a_text_is_read_once_per_process_an_edited_file_again_and_a_refused_one_every_time(tmp_path):
    text = "name: kept\nv: 0.3\nparticles: {B: {gap: 0.5}}\n"
    first = parse(text, "a.yaml", "a")
    assert parse(text, "a.yaml", "a") is first  # kept: the same frozen scenario
    assert parse(text, "b.yaml", "b") is not first  # another source or name is read on its own
    path = tmp_path / "s.yaml"
    path.write_text(text)
    assert load(str(path)).v == 0.3
    path.write_text(text.replace("0.3", "0.4"))  # edited between two loads of one process
    assert load(str(path)).v == 0.4
    path.write_text("v: 0.3\nparticles: {B: {gap: -1}}\n")
    for _ in range(2):  # refused each time, with its own sentence
        with pytest.raises(ScenarioError, match=r"s\.yaml, line 2: "):
            load(str(path))


# --- the work of reading a file is bounded by its size, whatever its shape (issue 6, items 6, 7) ------------

def _laughs(levels: int = 10, width: int = 9) -> str:
    """Nested anchors, each a list of `width` aliases to the one before: width**levels strings from ~600 bytes."""
    lists = ["&a0 [" + ", ".join(['"xxxxxxxxxx"'] * width) + "]"]
    lists += [f"&a{k} [" + ", ".join([f"*a{k - 1}"] * width) + "]" for k in range(1, levels)]
    return "[" + ", ".join(lists) + "]"


def _merges(levels: int = 10, width: int = 9) -> str:
    """Nested merge keys: each mapping merges the one before `width` times."""
    maps = ["m0: &m0 {" + ", ".join(f"k{i}: {i}" for i in range(width)) + "}"]
    maps += [f"m{k}: &m{k} {{<<: [" + ", ".join([f"*m{k - 1}"] * width) + "]}" for k in range(1, levels)]
    return "{" + ", ".join(maps) + "}"


TOO_MANY = ("the file stands for more than 1,000 keys and values once its aliases (*name) and merge keys (<<) "
            "are expanded; a scenario needs a few dozen.")
TOO_DEEP = "the lists and mappings are nested more than 16 deep; a scenario needs 4."


@pytest.mark.parametrize("text, message", [
    (f"name: {_laughs()}\nv: 0.6\nparticles: {{B: {{gap: 0.5}}}}\n", "s.yaml, line 1: " + TOO_MANY),
    (f"v: 0.6\nparticles: {{B: {{gap: 0.5}}}}\ndescription: {_laughs()}\n", "s.yaml, line 3: " + TOO_MANY),
    (f"v: 0.6\nparticles: {{B: {{gap: 0.5}}}}\ndescription: {_merges()}\n", "s.yaml, line 3: " + TOO_MANY),
    (f"v: 0.6\nparticles: {{B: {{gap: 0.5, mass: {_laughs()}}}}}\n", "s.yaml, line 2: " + TOO_MANY),
    (f"v: 0.6\n? {_laughs()}\n: 1\n", "s.yaml, line 2: " + TOO_MANY),  # a key
    (f"v: 0.6\nparticles: {{B: {{gap: 0.5}}}}\n<<: {_merges()}\n", "s.yaml, line 3: " + TOO_MANY),
    ("v: 0.6\nparticles: {B: {gap: 0.5}}\ndescription: [" + ", ".join(["1"] * 2000) + "]\n",
     "s.yaml, line 3: " + TOO_MANY),  # no alias at all: plainly too long
    ("name: " + "[" * 600 + "]" * 600 + "\nv: 0.6\n", "s.yaml, line 1: " + TOO_DEEP),
    ("v: 0.6\ndescription: " + "{a: " * 2000 + "1" + "}" * 2000 + "\n", "s.yaml, line 2: " + TOO_DEEP),
    ("v: 0.6\ndescription:\n" + "".join("  " * k + "- \n" for k in range(1, 40)), "s.yaml, line 18: " + TOO_DEEP),
    # deeper only once expanded: each list holds an alias to the one before
    ("x: [&d0 [1]" + "".join(f", &d{k} [*d{k - 1}]" for k in range(1, 20)) + "]\n",
     "s.yaml, line 1: the lists and mappings are nested more than 16 deep once the aliases (*name) are expanded; "
     "a scenario needs 4."),
    ("name: &a [*a]\nv: 0.6\n", "s.yaml, line 1: an alias refers to a list or mapping that contains it; "
                                "write the values out instead."),
])
def test_oversized_or_deep_yaml_is_refused_quickly_whatever_its_shape(text, message):
    import time

    start = time.process_time()  # this process's CPU time: a machine busy with other work does not count
    assert refused(text) == message
    assert time.process_time() - start < 1.0


@pytest.mark.parametrize("key, text, shown", [
    ("name", "[a, b]", "a list"),
    ("name", "{a: b}", "a mapping"),
    ("description", "[a]", "a list"),
])
def test_a_list_or_mapping_where_text_is_wanted_is_refused_unbuilt(key, text, shown, monkeypatch):
    import yaml

    def never(*args, **kwargs):
        raise AssertionError("a list or mapping was built")

    monkeypatch.setattr(yaml.constructor.SafeConstructor, "construct_sequence", never)
    monkeypatch.setattr(yaml.constructor.SafeConstructor, "construct_mapping", never)
    assert refused(f"v: 0.6\nparticles: {{B: {{gap: 0.5}}}}\n{key}: {text}\n") == (
        f"s.yaml, line 3: {key} must be text, got {shown}.")


def test_anchors_and_merge_keys_within_bounds_are_read():
    s = parse("v: 0.6\nparticles:\n  A: &p {gap: 0.5, mass: 2}\n  B: {<<: *p, speed: 0.3}\n", "s.yaml", "s")
    assert s.particle("A") == Particle("A", mass=2.0, gap=0.5)
    assert s.particle("B") == Particle("B", mass=2.0, speed=0.3, gap=0.5)


def test_a_file_larger_than_the_limit_is_refused_before_it_is_read(tmp_path):
    from rodparadox.io.scenario import MAX_FILE_BYTES

    big = tmp_path / "big.yaml"
    big.write_text("v: 0.6\nparticles: {B: {gap: 0.5}}\n#" + "x" * MAX_FILE_BYTES + "\n")
    with pytest.raises(ScenarioError) as info:
        load(str(big))
    assert str(info.value) == f"scenario file '{big}' is larger than 100,000 bytes; a scenario is a few lines of YAML."


# --- names and descriptions: printable text (item 13) --------------------------------------------------------

@pytest.mark.parametrize("line, message", [
    ('name: "tab\\there"', "name must be printable text, but it contains a tab (U+0009)."),
    ('name: "two\\nlines"', "name must be printable text, but it contains a line break (U+000A)."),
    ('name: "nul\\0"', "name must be printable text, but it contains a NUL (U+0000)."),
    ('name: "bell\\a"', "name must be printable text, but it contains a control character (U+0007)."),
    ('description: "a\\tb"',
     "description must be printable text, but it contains a tab (U+0009); only line breaks are allowed."),
    ('description: "esc\\e[31m"',
     "description must be printable text, but it contains a control character (U+001B); only line breaks are allowed."),
    ("name: " + "n" * 201, "name must be at most 200 characters, got 201; say more in description."),
])
def test_control_characters_and_overlong_names_are_refused_with_key_and_line(line, message):
    assert refused(f"v: 0.6\nparticles: {{B: {{gap: 0.5}}}}\n{line}\n") == f"s.yaml, line 3: {message}"


def test_a_description_may_run_over_several_lines():
    s = parse("v: 0.6\nparticles: {B: {gap: 0.5}}\nname: " + "n" * 200 + "\ndescription: |\n  one\n  two\n",
              "s.yaml", "s")
    assert s.description == "one\ntwo\n" and len(s.name) == 200


def test_a_file_name_with_a_control_character_is_refused(tmp_path):
    bad = tmp_path / "tab\there.yaml"
    bad.write_text("v: 0.6\nparticles: {B: {gap: 0.5}}\n")
    with pytest.raises(ScenarioError) as info:
        load(str(bad))
    assert str(info.value) == f"{bad}: name must be printable text, but it contains a tab (U+0009)."


# --- which file a SCENARIO names (item 14) ----------------------------------------------------------------

def test_an_existing_file_wins_over_a_builtin_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "fig2").write_text("name: mine\nv: 0.3\nparticles: {B: {gap: 0.5}}\n")
    assert (load("fig2").name, load("fig2").v) == ("mine", 0.3)
    (tmp_path / "fig1").mkdir()  # a folder does not shadow the built-in
    assert load("fig1") == load(str(configs_folder() / "fig1.yaml"))


@pytest.mark.parametrize("given, stem", [
    ("fig2", "fig2"), ("my.yaml", "my"), ("dir/My.YAML", "My"), ("x.yml", "x"), ("x.YML", "x"),
    ("dir/scene.v2", "scene.v2"), ("a.b.yaml", "a.b"),
])
def test_stem_of_drops_any_yaml_extension_in_any_case(given, stem):
    from rodparadox.io.scenario import stem_of

    assert stem_of(given) == stem


def test_upper_case_extensions_are_yaml_files(tmp_path):
    upper = tmp_path / "X.YAML"
    upper.write_text("v: 0.6\nparticles: {B: {gap: 0.5}}\n")
    assert load(str(upper)).name == "X"


def test_an_empty_scenario_name_is_refused():
    with pytest.raises(ScenarioError) as info:
        load("")
    assert str(info.value) == "SCENARIO is empty; give a built-in name (see 'sears-paradox list') or a YAML file."
