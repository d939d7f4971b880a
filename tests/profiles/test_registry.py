"""Finding profiles: built-in, the user's folder, extra folders and entry points; lazy code import."""
import importlib.metadata
import json
import os
import shutil
import subprocess
import sys
import textwrap

import pytest
from profile_copies import HOBBIT_DIR, REPO, SHARED_TOOLBOXES, copy_profile

from rockly_desktop.core import paths
from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.profiles.registry import ENTRY_POINT_GROUP, ProfileRegistry, discover_locations


@pytest.fixture(autouse=True)
def own_user_folder(tmp_path, monkeypatch):
    """Profiles of the real user never leak in; the data root is the source tree."""
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "xdg"))
    monkeypatch.delenv("ROCKLY_DATA_DIR", raising=False)
    return tmp_path / "xdg" / "rockly" / "profiles"


@pytest.fixture
def restore_imports(monkeypatch):
    """Undo what importing profile code does to sys.path and sys.modules."""
    monkeypatch.setattr(sys, "path", list(sys.path))
    before = set(sys.modules)
    yield
    for name in set(sys.modules) - before:
        if name.startswith(("rockly_hobbit", "testbot_")):
            del sys.modules[name]


def install_distribution(site, dist_name, entry_points: dict):
    """Write a minimal installed distribution (dist-info with entry points) into ``site``."""
    dist_info = site / f"{dist_name}-0.1.dist-info"
    dist_info.mkdir(parents=True)
    (dist_info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {dist_name}\nVersion: 0.1\n", encoding="utf-8")
    lines = [f"[{ENTRY_POINT_GROUP}]"] + [f"{name} = {value}" for name, value in entry_points.items()]
    (dist_info / "entry_points.txt").write_text("\n".join(lines) + "\n", encoding="utf-8")


def profile_ids(registry):
    return set(registry.profiles)


# --- built-in, user, extra ---------------------------------------------------------------


def test_builtin_hobbit_is_found_and_is_the_default():
    registry = ProfileRegistry.discover()

    assert registry.errors == []
    hobbit = registry.get("hobbit")
    assert hobbit.root == HOBBIT_DIR
    assert hobbit.source == "built-in"
    assert registry.default() is hobbit
    assert hobbit.block_types <= registry.all_block_types()
    with pytest.raises(KeyError):
        registry.get("r2d2")


def test_profile_in_the_users_xdg_folder_is_found(own_user_folder):
    copy_profile(own_user_folder / "robo", "robo")

    registry = ProfileRegistry.discover()

    assert registry.errors == []
    assert {"hobbit", "robo"} <= profile_ids(registry)
    robo = registry.get("robo")
    assert robo.source == "user"
    assert robo.root == own_user_folder / "robo"
    assert registry.default().id == "hobbit"


def test_without_xdg_data_home_the_users_folder_is_under_home(tmp_path, monkeypatch):
    monkeypatch.delenv("XDG_DATA_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    folder = tmp_path / "home" / ".local" / "share" / "rockly" / "profiles"
    copy_profile(folder / "robo", "robo")

    assert paths.user_profiles_dir() == folder
    assert ProfileRegistry.discover().get("robo").source == "user"


def test_profiles_in_extra_folders_are_found_and_other_folders_ignored(tmp_path):
    extra = tmp_path / "extra"
    copy_profile(extra / "other", "other")
    (extra / "not_a_profile").mkdir()
    (extra / "not_a_profile" / "README.md").write_text("hello", encoding="utf-8")
    (extra / "loose_file.yaml").write_text("id: nope\n", encoding="utf-8")

    registry = ProfileRegistry.discover(extra_dirs=[extra, tmp_path / "missing"])

    assert registry.errors == []
    assert profile_ids(registry) >= {"hobbit", "other"}
    assert "nope" not in profile_ids(registry)
    assert registry.get("other").source == "extra"


def test_locations_come_in_priority_order(tmp_path, own_user_folder):
    copy_profile(own_user_folder / "robo", "robo")
    copy_profile(tmp_path / "extra" / "other", "other")
    sources = [(location.folder.name, location.source) for location in discover_locations([tmp_path / "extra"])]
    kinds = [source for _, source in sources]
    assert ("hobbit", "built-in") in sources
    assert kinds == sorted(kinds, key=["built-in", "user", "extra"].index)
    assert sources.index(("robo", "user")) < sources.index(("other", "extra"))


def test_broken_profile_is_recorded_and_the_others_still_load(tmp_path):
    extra = tmp_path / "extra"
    broken = copy_profile(extra / "a_broken", "Not An Id")
    copy_profile(extra / "b_good", "good")

    registry = ProfileRegistry.discover(extra_dirs=[extra])

    assert profile_ids(registry) >= {"hobbit", "good"}
    assert len(registry.errors) == 1
    error = registry.errors[0]
    assert isinstance(error, ManifestError)
    assert (error.path, error.field) == (str(broken.path("profile.yaml")), "id")


def test_profile_with_a_broken_block_file_is_recorded_naming_that_file(own_user_folder):
    robo = copy_profile(own_user_folder / "robo", "robo")
    robo.write_text("blocks.yaml", "blocks:\n  - type: [unclosed\n")

    registry = ProfileRegistry.discover()

    assert "robo" not in registry.profiles
    assert [error.path for error in registry.errors] == [str(robo.path("blocks.yaml"))]
    assert "not valid YAML at line" in registry.errors[0].problem
    assert "hobbit" in registry.profiles


def test_duplicate_id_is_recorded_and_the_first_one_kept(tmp_path):
    duplicate = copy_profile(tmp_path / "extra" / "hobbit_copy")

    registry = ProfileRegistry.discover(extra_dirs=[tmp_path / "extra"])

    assert registry.get("hobbit").root == HOBBIT_DIR
    assert len(registry.errors) == 1
    error = registry.errors[0]
    assert error.path == str(duplicate.path("profile.yaml"))
    assert error.field == "id"
    assert error.problem == f"'hobbit' is already provided by {HOBBIT_DIR} (built-in); this copy is ignored"


def test_user_profile_wins_over_an_extra_folder_with_the_same_id(tmp_path, own_user_folder):
    copy_profile(own_user_folder / "robo", "robo")
    copy_profile(tmp_path / "extra" / "robo", "robo")

    registry = ProfileRegistry.discover(extra_dirs=[tmp_path / "extra"])

    assert registry.get("robo").source == "user"
    assert [error.field for error in registry.errors] == ["id"]


def test_without_hobbit_the_first_profile_is_the_default(tmp_path, monkeypatch):
    data = tmp_path / "data"
    copy_profile(data / "profiles" / "robo", "robo")
    shutil.copytree(SHARED_TOOLBOXES, data / "toolboxes")
    monkeypatch.setenv("ROCKLY_DATA_DIR", str(data))

    registry = ProfileRegistry.discover()

    assert registry.errors == []
    assert profile_ids(registry) == {"robo"}
    assert registry.default().id == "robo"


# --- entry points --------------------------------------------------------------------------


def test_profile_installed_as_a_python_package_is_found_by_its_entry_point(tmp_path, monkeypatch):
    site = tmp_path / "site"
    install_distribution(site, "rockly_testbot", {"testbot": "rockly_testbot_profile"})
    package = copy_profile(site / "rockly_testbot_profile", "testbot")
    (package.root / "__init__.py").write_text('"""A Rockly profile shipped as a package."""\n', encoding="utf-8")
    monkeypatch.syspath_prepend(str(site))

    names = [entry_point.name for entry_point in importlib.metadata.entry_points(group=ENTRY_POINT_GROUP)]
    assert "testbot" in names, "importlib.metadata must see the test distribution"

    registry = ProfileRegistry.discover()

    assert registry.errors == []
    testbot = registry.get("testbot")
    assert testbot.source == "entry point testbot"
    assert testbot.root == package.root
    assert "hobbit" in registry.profiles
    assert "rockly_testbot_profile" not in sys.modules, "finding the package must not import it"


def test_without_a_distribution_declaring_profiles_discovery_leaves_importlib_metadata_unimported(tmp_path):
    # importlib.metadata brings the email package: a tenth of the window's start, for the plugins most never have.
    script = ("import json, sys; from rockly_desktop.profiles.registry import ProfileRegistry; "
              "registry = ProfileRegistry.discover(); "
              "print(json.dumps([sorted(registry.profiles), 'importlib.metadata' in sys.modules]))")
    env = {key: value for key, value in os.environ.items() if key != "ROCKLY_DATA_DIR"}
    env["XDG_DATA_HOME"] = str(tmp_path / "xdg")
    result = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, env=env,
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == [["hobbit", "turtlebot"], False]


def test_a_profile_installed_as_an_old_style_egg_folder_is_found(tmp_path, monkeypatch):
    egg = tmp_path / "rockly_eggbot-0.1-py3.egg"  # easy_install's layout: the egg folder itself is on sys.path
    (egg / "EGG-INFO").mkdir(parents=True)
    (egg / "EGG-INFO" / "PKG-INFO").write_text("Metadata-Version: 1.1\nName: rockly-eggbot\nVersion: 0.1\n")
    (egg / "EGG-INFO" / "entry_points.txt").write_text(f"[{ENTRY_POINT_GROUP}]\neggbot = rockly_eggbot_profile\n")
    copy_profile(egg / "rockly_eggbot_profile", "eggbot")
    monkeypatch.syspath_prepend(str(egg))

    registry = ProfileRegistry.discover()

    assert registry.get("eggbot").source == "entry point eggbot"


@pytest.mark.parametrize("value, reason", [
    ("rockly_no_such_package_here", "no such package is installed"),
    ("rockly_no_such_parent_here.profile", "ModuleNotFoundError: No module named 'rockly_no_such_parent_here'"),
    ("rockly_single_module_profile", "it is a module, not a package folder holding profile.yaml"),
], ids=["missing package", "missing parent package", "a plain module"])
def test_entry_point_naming_no_profile_package_is_recorded_and_the_others_still_load(tmp_path, monkeypatch, value,
                                                                                     reason):
    site = tmp_path / "site"
    install_distribution(site, "rockly_ghost", {"ghost": value})
    (site / "rockly_single_module_profile.py").write_text("", encoding="utf-8")
    monkeypatch.syspath_prepend(str(site))

    registry = ProfileRegistry.discover()

    assert "hobbit" in registry.profiles
    assert len(registry.errors) == 1
    error = registry.errors[0]
    assert error.path == "entry point ghost"
    assert error.problem == f"'{value}' ({ENTRY_POINT_GROUP}): {reason}"


def test_entry_point_package_with_a_broken_profile_is_recorded(tmp_path, monkeypatch):
    site = tmp_path / "site"
    install_distribution(site, "rockly_badbot", {"badbot": "rockly_badbot_profile"})
    package = copy_profile(site / "rockly_badbot_profile", "badbot")
    package.edit("profile.yaml", lambda data: data.pop("api"))
    monkeypatch.syspath_prepend(str(site))

    registry = ProfileRegistry.discover()

    assert "badbot" not in registry.profiles
    assert [(error.path, error.field) for error in registry.errors] == [(str(package.path("profile.yaml")), "api")]


# --- profile code is imported only on demand ---------------------------------------------------


def test_discovery_imports_no_profile_code_and_no_qt_in_a_fresh_interpreter(tmp_path):
    script = textwrap.dedent("""
        import json, sys
        from rockly_desktop.profiles.registry import ProfileRegistry
        registry = ProfileRegistry.discover()
        report = {"errors": [str(error) for error in registry.errors],
                  "after_discover": sorted(name for name in sys.modules if name.startswith("rockly_hobbit")),
                  "qt": sorted(name for name in sys.modules if name.startswith("PySide6"))}
        api = registry.get("hobbit").load_object("api")
        report["after_load"] = sorted(name for name in sys.modules if name.startswith("rockly_hobbit"))
        report["api"] = f"{api.__module__}:{api.__qualname__}"
        print(json.dumps(report))
    """)
    env = {key: value for key, value in os.environ.items() if key != "ROCKLY_DATA_DIR"}
    env["XDG_DATA_HOME"] = str(tmp_path / "xdg")
    result = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, env=env,
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)

    assert report["errors"] == []
    assert report["after_discover"] == []
    assert report["qt"] == []
    # the commands know the house they drive in, and the base's own speeds (base)
    assert report["after_load"] == ["rockly_hobbit", "rockly_hobbit.api", "rockly_hobbit.base", "rockly_hobbit.world"]
    assert report["api"] == "rockly_hobbit.api:Hobbit"


def test_discovery_does_not_import_the_hobbit_api_in_this_process(monkeypatch):
    for name in [name for name in sys.modules if name.startswith("rockly_hobbit")]:
        monkeypatch.delitem(sys.modules, name)

    registry = ProfileRegistry.discover()
    registry.get("hobbit").editor_config("de")

    assert "rockly_hobbit.api" not in sys.modules
    assert "rockly_hobbit" not in sys.modules


@pytest.fixture
def codebot(tmp_path):
    """A profile whose commands live in code/testbot_commands.py (python_path: code)."""
    bot = copy_profile(tmp_path / "testbot", "testbot")
    (bot.root / "code").mkdir()
    def use_own_code(data):
        data.update(api="testbot_commands:TestBot", python_path="code")
        data.pop("simulator", None)
        data.pop("simulator_view", None)

    bot.edit("profile.yaml", use_own_code)
    return bot


def test_load_object_imports_from_the_profiles_python_path(codebot, restore_imports):
    (codebot.root / "code" / "testbot_commands.py").write_text("class TestBot:\n    pass\n", encoding="utf-8")
    profile = load_profile(codebot.root, SHARED_TOOLBOXES)
    assert "testbot_commands" not in sys.modules

    commands = profile.load_object("api")

    assert commands.__name__ == "TestBot"
    assert sys.modules["testbot_commands"].__file__ == str(codebot.root / "code" / "testbot_commands.py")
    assert str(codebot.root / "code") in sys.path


@pytest.mark.parametrize("module_text, api, problem", [
    (None, "testbot_missing:TestBot",
     "cannot import testbot_missing:TestBot: ModuleNotFoundError: No module named 'testbot_missing'"),
    ("class Other:\n    pass\n", "testbot_commands:TestBot",
     "cannot import testbot_commands:TestBot: AttributeError: module 'testbot_commands' has no attribute 'TestBot'"),
    ("raise RuntimeError('the robot driver is missing')\n", "testbot_commands:TestBot",
     "cannot import testbot_commands:TestBot: RuntimeError: the robot driver is missing"),
    ("def broken(:\n", "testbot_commands:TestBot", "cannot import testbot_commands:TestBot: SyntaxError:"),
], ids=["missing module", "missing name", "module raises", "syntax error"])
def test_bad_import_gives_manifest_error_naming_the_field(codebot, restore_imports, module_text, api, problem):
    if module_text is not None:
        (codebot.root / "code" / "testbot_commands.py").write_text(module_text, encoding="utf-8")
    codebot.edit("profile.yaml", lambda data: data.update(api=api))
    profile = load_profile(codebot.root, SHARED_TOOLBOXES)

    with pytest.raises(ManifestError) as caught:
        profile.load_object("api")

    assert caught.value.path == str(codebot.path("profile.yaml"))
    assert caught.value.field == "api"
    assert caught.value.problem.startswith(problem)


def test_load_object_of_a_field_the_profile_does_not_set(codebot, restore_imports):
    profile = load_profile(codebot.root, SHARED_TOOLBOXES)
    with pytest.raises(ManifestError) as caught:
        profile.load_object("simulator")
    assert (caught.value.field, caught.value.problem) == ("simulator", "is not set in this profile")


def test_real_hobbit_api_is_a_robot_commands_class(restore_imports):
    from rockly_desktop.sdk import RobotCommands

    hobbit = load_profile(HOBBIT_DIR, SHARED_TOOLBOXES)
    commands = hobbit.load_object("api")
    assert issubclass(commands, RobotCommands)
    assert commands.__module__ == "rockly_hobbit.api"
    assert sys.modules["rockly_hobbit.api"].__file__ == str(REPO / "profiles" / "hobbit" / "rockly_hobbit" / "api.py")
