"""Finding robot profiles: built-in folder, the user's folder, and Python entry points.

One loader serves all three. A broken profile is recorded with its error and skipped;
the others still load.
"""
import importlib.machinery
import importlib.util
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path

from rockly_desktop.core import paths
from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ManifestError, RocklyError
from rockly_desktop.profiles.manifest import MANIFEST_NAME
from rockly_desktop.profiles.packs.merge import with_packs
from rockly_desktop.profiles.packs.pack import discover_packs
from rockly_desktop.profiles.packs.validation import BlockMakerError
from rockly_desktop.profiles.profile import Profile, load_profile

ENTRY_POINT_GROUP = "rockly.profiles"


@dataclass(frozen=True)
class ProfileLocation:
    """A folder that may hold a profile, and where it was found."""

    folder: Path
    source: str
    problem: str = None  # set when the place was named (an entry point) but holds no profile folder


def _folders_in(parent: Path, source: str) -> list:
    if not parent.is_dir():
        return []
    return [ProfileLocation(child, source) for child in sorted(parent.iterdir())
            if child.is_dir() and (child / MANIFEST_NAME).exists()]


def _may_be_declared(group: str) -> bool:
    """False when no installed distribution declares entry points of ``group``: no ``entry_points.txt`` of a
    ``.dist-info`` or ``.egg-info`` folder on ``sys.path`` names it, and nothing but such folders (no zip, no
    egg, no finder but Python's own) could hold distributions. True when one may (``importlib.metadata`` then
    says which)."""
    if any(hasattr(finder, "find_distributions") for finder in sys.meta_path
           if finder is not importlib.machinery.PathFinder):
        return True
    for entry in sys.path:
        try:
            children = list(os.scandir(entry or "."))
        except NotADirectoryError:
            return True  # a zip file or an egg: importlib.metadata looks inside
        except OSError:
            continue
        if str(entry).lower().endswith(".egg"):
            return True  # an old-style egg folder keeps its entry points in EGG-INFO
        for child in children:
            if child.name.lower().endswith((".dist-info", ".egg-info")) and child.is_dir():
                try:
                    with open(os.path.join(child.path, "entry_points.txt"), encoding="utf-8") as declared:
                        if group in declared.read():
                            return True
                except OSError:
                    continue
    return False


def _entry_points(group: str):
    """The installed entry points of ``group`` (Python 3.8 and 3.9 have them only as a dict of groups).

    ``importlib.metadata`` (with the email package it imports: 30–40 ms, a tenth of the window's start) is
    imported only when some distribution may declare the group."""
    if not _may_be_declared(group):
        return ()
    import importlib.metadata

    installed = importlib.metadata.entry_points()
    if hasattr(installed, "select"):
        return installed.select(group=group)
    return installed.get(group, ())


def _entry_point_locations() -> list:
    """Profiles installed as Python packages: the entry point names a package holding profile.yaml."""
    locations = []
    for entry_point in _entry_points(ENTRY_POINT_GROUP):
        package = entry_point.value.split(":")[0].strip()
        source = f"entry point {entry_point.name}"
        try:
            spec = importlib.util.find_spec(package)
        except Exception as error:
            spec, reason = None, f"{type(error).__name__}: {error}"
        else:
            reason = "no such package is installed"
        if spec and spec.submodule_search_locations:
            locations.append(ProfileLocation(Path(list(spec.submodule_search_locations)[0]), source))
        else:
            if spec:
                reason = "it is a module, not a package folder holding profile.yaml"
            locations.append(ProfileLocation(Path(package), source,
                                             f"'{entry_point.value}' ({ENTRY_POINT_GROUP}): {reason}"))
    return locations


def discover_locations(extra_dirs=()) -> list:
    """Every place a profile may be, in priority order (built-in first)."""
    locations = _folders_in(paths.builtin_profiles_dir(), "built-in")
    locations += _folders_in(paths.user_profiles_dir(), "user")
    for folder in extra_dirs:
        locations += _folders_in(Path(folder), "extra")
    return locations + _entry_point_locations()


@dataclass
class ProfileRegistry:
    """The installed profiles that loaded (with the block packs that add to them merged in), and
    the errors of those that did not."""

    profiles: dict = field(default_factory=dict)
    errors: list = field(default_factory=list)
    base_profiles: dict = field(default_factory=dict)  # the profiles as their folders have them, without packs
    packs: dict = field(default_factory=dict)          # the installed block packs by id (packs.pack.Pack)
    pack_errors: list = field(default_factory=list)    # why a pack is not merged: broken, or its profile missing

    @classmethod
    def discover(cls, extra_dirs=()) -> "ProfileRegistry":
        """Load every profile found; a broken or duplicate one is recorded and skipped."""
        registry = cls()
        shared = paths.shared_toolboxes_dir()
        for location in discover_locations(extra_dirs):
            if location.problem:
                registry.errors.append(ManifestError(location.source, None, location.problem))
                continue
            try:
                profile = load_profile(location.folder, shared, location.source)
            except ManifestError as error:
                registry.errors.append(error)
                continue
            if profile.id in registry.profiles:
                first = registry.profiles[profile.id]
                registry.errors.append(ManifestError(
                    location.folder / MANIFEST_NAME, "id",
                    f"'{profile.id}' is already provided by {first.root} ({first.source}); this copy is ignored"))
                continue
            registry.profiles[profile.id] = profile
        registry.base_profiles = dict(registry.profiles)
        registry.reload_packs()
        return registry

    def reload_packs(self, folder=None) -> None:
        """Read the block packs again (from ``folder``, default the user's) and merge each into the
        profile it adds to: what the window calls after a block was saved or a pack imported, then
        showing ``get(profile_id)`` again. The profiles themselves are not read again."""
        packs, pack_errors = discover_packs(folder)
        merged = dict(self.base_profiles)
        for pack in packs.values():
            if pack.adds_to not in merged:
                pack_errors.append(BlockMakerError(app_local_text(
                    "pack_broken", pack=pack.id, problem=app_local_text(
                        "pack_profile_missing", profile=pack.adds_to, installed=", ".join(merged) or "-"))))
        for profile_id, profile in merged.items():
            merged[profile_id], errors = with_packs(profile, packs.values())
            pack_errors += errors
        self.profiles, self.packs, self.pack_errors = merged, packs, pack_errors

    def pack(self, pack_id: str):
        """The installed block pack ``pack_id``; KeyError if there is none."""
        return self.packs[pack_id]

    def get(self, profile_id: str) -> Profile:
        """The profile with this id; KeyError if it is not installed."""
        return self.profiles[profile_id]

    def default(self) -> Profile:
        """The profile Rockly starts with: the first one found (built-in ones first, by folder name)."""
        if not self.profiles:
            raise RocklyError("no robot profile is installed")
        return next(iter(self.profiles.values()))

    def all_block_types(self) -> set:
        """Block types any installed profile defines."""
        return set().union(*(profile.block_types for profile in self.profiles.values()))
