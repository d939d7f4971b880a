"""A loaded robot profile: validated data, with its Python code imported only on demand."""
import importlib
import sys
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

from rockly_desktop.core.app_texts import app_catalogue
from rockly_desktop.core.catalogue import Catalogue
from rockly_desktop.core.errors import ManifestError, RocklyError
from rockly_desktop.core.ros_definitions import DefinitionCatalog
from rockly_desktop.core.workspace_blocks import block_types_in_workspace
from rockly_desktop.profiles.blocks import BlockSpec, read_blocks
from rockly_desktop.profiles.i18n import localize
from rockly_desktop.profiles.manifest import MANIFEST_NAME, read_manifest
from rockly_desktop.profiles.toolbox import (
    category_names,
    level_categories,
    read_toolbox,
    shared_definition_files,
    toolbox_block_types,
    toolbox_json,
)


@dataclass(frozen=True, eq=False)
class Profile:
    """A robot profile read from its folder (manifest, blocks, toolbox); no code imported."""

    id: str
    name: object
    version: str
    root: Path
    source: str
    manifest: dict
    blocks: tuple
    toolbox_categories: list
    shared_blocks: tuple = ()
    packs: tuple = ()  # the block packs merged in (``packs.merge.PackInfo``), in the order they were added

    def display_name(self, language: str = "en") -> str:
        """The profile's name for people, in ``language``."""
        return self.localize(self.name, language)

    @cached_property
    def texts(self) -> Catalogue:
        """The profile's own catalogue: ``locale/`` beside its manifest (its code's words; other
        languages for its YAML texts)."""
        return Catalogue(self.root / "locale")

    def localize(self, value, language: str):
        """``value`` (manifest, block or toolbox data) with its texts in ``language``: as the YAML
        spells them, else from the profile's catalogue, else Rockly's, else English."""
        return localize(value, language, (self.texts, app_catalogue()))

    @property
    def block_types(self) -> set:
        """Block types this profile offers: its own and those its shared categories bring."""
        return {spec.type for spec in self.blocks + self.shared_blocks}

    @property
    def own_block_types(self) -> set:
        """Block types the profile's own block file defines."""
        return {spec.type for spec in self.blocks}

    def block(self, block_type: str) -> BlockSpec:
        """The BlockSpec of one of this profile's blocks; KeyError if it has none of that type."""
        for spec in self.blocks + self.shared_blocks:
            if spec.type == block_type:
                return spec
        raise KeyError(block_type)

    def pack_of(self, block_type: str):
        """The id of the merged block pack defining ``block_type``, or None (the profile's own, or unknown)."""
        return next((pack.id for pack in self.packs if block_type in pack.block_types), None)

    def packs_used(self, workspace: dict) -> dict:
        """``{pack id: version}`` of the merged packs whose blocks ``workspace`` (Blockly JSON) uses:
        what a program file records, so that opening it without a pack can say which is missing."""
        used = set(block_types_in_workspace(workspace or {}))
        return {pack.id: pack.version for pack in self.packs if used & pack.block_types}

    @property
    def legacy_fields(self) -> dict:
        """Old field names/values of saved programs, per block type."""
        return self.manifest.get("legacy_fields", {})

    @property
    def api_target(self) -> str:
        """The ``module:Class`` of the robot's commands, as the manifest names it."""
        return self.manifest["api"]

    @property
    def safe_stop(self) -> list:
        """What 'stop' means for this robot: its list of ``{publish: ...}``/``{cancel_goals: ...}`` actions."""
        return self.manifest.get("safe_stop", [])

    @property
    def ros_interface(self) -> dict:
        """The robot's ROS interface: ``subscribes``, ``publishes``, ``services``, ``actions``, ``streams``."""
        return self.manifest.get("ros_interface", {})

    @property
    def state_panels(self) -> list:
        """The Robot state dock's panels: ``[{panel: title, rows: [{label, topic, field, ...}]}]``."""
        return self.manifest.get("state", [])

    @property
    def message_folders(self) -> list:
        """The folders of ROS definitions the profile ships (its manifest's ``messages``; none or one), then its
        merged packs' (the definitions of types their blocks use that the robot said)."""
        folder = self.manifest.get("messages")
        return ([self.root / folder] if folder else []) + [pack.message_folder for pack in self.packs
                                                           if pack.message_folder is not None]

    @property
    def ros_versions(self) -> dict:
        """What differs per ROS version: ``{NAME: {ros1|ros2|DISTRIBUTION: TYPE}}``
        (see ``robot/wrappers/ros_versions.py``)."""
        return self.manifest.get("ros_versions", {})

    @property
    def velocity_topics(self) -> list:
        """The drive interface: the ``geometry_msgs/Twist`` topics a teacher's speed limits clamp."""
        return self.manifest.get("velocity_topics", [])

    @property
    def own_speed(self) -> dict:
        """Motions at the robot's own speed: ``{speed, turn, topics, services, actions}`` ({}: none)."""
        return self.manifest.get("own_speed", {})

    @property
    def capabilities(self) -> list:
        """Parts a teacher can switch off: ``[{id, name, blocks, topics, services, actions}]``."""
        return self.manifest.get("capabilities", [])

    @property
    def levels(self) -> list:
        """Toolbox levels a teacher picks from: ``[{id, name, categories, blocks}]``."""
        return self.manifest.get("levels", [])

    def level(self, level_id):
        """The level with id ``level_id``, or None (the whole toolbox) for an unknown or no id."""
        return next((level for level in self.levels if level["id"] == level_id), None)

    def hidden_blocks(self, switched_off) -> set:
        """Block types of the capabilities whose ids are in ``switched_off``, and the made blocks of
        packs that use one of their topics, services or actions."""
        hidden = set()
        for capability in self.capabilities:
            if capability["id"] in switched_off:
                hidden.update(capability.get("blocks", []))
                names = {*capability.get("topics", ()), *capability.get("services", ()), *capability.get("actions", ())}
                hidden.update(block for pack in self.packs for block, name in pack.interfaces.items() if name in names)
        return hidden

    def simulator_view_class(self):
        """The simulator view's class (imported now), or None when the profile has no view.

        Raises ManifestError when the view is named but cannot be imported.
        """
        return self.load_object("simulator_view") if self.manifest.get("simulator_view") else None

    @property
    def has_simulator(self) -> bool:
        """True when the profile names a built-in simulator."""
        return bool(self.manifest.get("simulator"))

    def lesson_goals(self) -> list:
        """The goal kinds the profile adds to lessons (its ``lesson_goals``, imported now); [] without.
        Raises ManifestError when they are named but cannot be imported."""
        return list(self.load_object("lesson_goals")) if self.manifest.get("lesson_goals") else []

    @cached_property
    def ros_types(self) -> DefinitionCatalog:
        """The ROS types typed blocks offer: the common installed packages and the profile's own."""
        return DefinitionCatalog(self.message_folders)

    def toolbox(self, language: str, level_id=None, switched_off=()) -> dict:
        """Blockly's toolbox JSON for the level ``level_id`` (None: all of it), without the blocks of
        switched-off capabilities. Every block stays defined: programs using others still open."""
        categories = level_categories(self.toolbox_categories, self.level(level_id), self.hidden_blocks(switched_off))
        return toolbox_json(categories, language, (self.texts, app_catalogue()))

    def editor_config(self, language: str, level_id=None, switched_off=()) -> dict:
        """Everything the editor page needs for this profile, texts in ``language``, the toolbox
        for a level and the capabilities switched off (see ``toolbox``)."""
        return {
            "profile": self.id,
            "blocks": [spec.editor_config(language, (self.texts, app_catalogue()))
                       for spec in self.blocks + self.shared_blocks],
            "toolbox": self.toolbox(language, level_id, switched_off),
            "types": self.ros_types.editor_catalog,
            "madeBlocks": sorted(block for pack in self.packs for block in pack.interfaces),  # "Edit this block…"
        }

    def command_side(self) -> dict:
        """What a process of its own needs to make this profile's commands (``from_command_side``), as plain data:
        its id, version, folder, source, manifest and ROS definition folders (its packs' too)."""
        return {"id": self.id, "version": self.version, "root": str(self.root), "source": self.source,
                "manifest": self.manifest, "message_folders": [str(folder) for folder in self.message_folders]}

    @classmethod
    def from_command_side(cls, data: dict) -> "Profile":
        """The profile ``command_side`` described: its commands (``create('api', ...)``) and ROS types; no blocks."""
        profile = cls(data["id"], data["id"], data["version"], Path(data["root"]), data["source"], data["manifest"],
                      (), [])
        profile.__dict__["ros_types"] = DefinitionCatalog([Path(folder) for folder in data["message_folders"]])
        return profile

    def load_object(self, field_name: str, target: str = None):
        """Import and return the object a manifest field names as ``module:Name`` (``target``: the name it gives
        inside, e.g. ``program_menu``'s ``hook``).

        The profile's python_path is put on ``sys.path`` first. Raises ManifestError
        naming the field when the module or the name cannot be imported.
        """
        target = target or self.manifest.get(field_name)
        if not target:
            raise ManifestError(self.root / MANIFEST_NAME, field_name, "is not set in this profile")
        module_name, attr = target.split(":")
        code_dir = (self.root / self.manifest.get("python_path", ".")).resolve()
        if str(code_dir) not in sys.path:
            sys.path.append(str(code_dir))  # after everything else: a profile cannot shadow other modules
        try:
            module = importlib.import_module(module_name)
            found = getattr(module, attr)
        except (Exception, SystemExit) as error:  # any failure in profile code (even sys.exit) is reported
            raise ManifestError(self.root / MANIFEST_NAME, field_name,
                                f"cannot import {target}: {_failure(error)}") from error
        module_file = Path(getattr(module, "__file__", "") or "").resolve()
        if code_dir not in module_file.parents:
            raise ManifestError(self.root / MANIFEST_NAME, field_name,
                                f"{module_name} was found at {module_file}, not in the profile's folder "
                                f"(another profile or package uses the same name)")
        return found


    def create(self, field_name: str, *args, **kwargs):
        """Import the class a manifest field names and make one with ``args``.

        A failure inside the profile's code (other than a RocklyError it raises on
        purpose) becomes a ManifestError naming the field, never a traceback.
        """
        return self._make(field_name, self.manifest.get(field_name), args, kwargs)

    def program_menu(self, language: str):
        """The profile's way of offering the agent's programs on the robot's own UI (its ``program_menu`` hook, an
        SDK ``ProgramMenu``, with the manifest's settings), speaking ``language``; None when the profile declares
        none. ManifestError when the hook cannot be imported or started."""
        menu = self.manifest.get("program_menu")
        if not menu:
            return None
        return self._make("program_menu", menu["hook"], (language,),
                          {"offers_stop": menu.get("stop", False),
                           "answer_seconds": float(menu.get("answer_seconds", 60)),
                           "offers_pairing": menu.get("pairing", False)})

    def _make(self, field_name: str, target: str, args, kwargs):
        found = self.load_object(field_name, target)
        try:
            return found(*args, **kwargs)
        except RocklyError:
            raise
        except (Exception, SystemExit) as error:
            raise ManifestError(self.root / MANIFEST_NAME, field_name,
                                f"{target} failed to start: {_failure(error)}") from error


def _failure(error: BaseException) -> str:
    """A failure of profile code in words: the exception's type and message."""
    if isinstance(error, SystemExit):
        return f"the code called sys.exit({error.code!r})"
    return f"{type(error).__name__}: {error}"


def _check_levels_and_capabilities(path: Path, manifest: dict, categories: list):
    """Raise ManifestError when a level or capability names a category or block the toolbox lacks."""
    names = set().union(*(category_names(category) for category in categories))
    types = toolbox_block_types(categories)
    for field in ("levels", "capabilities"):
        for index, entry in enumerate(manifest.get(field, [])):
            categories_named = entry.get("categories", [])
            for name in [] if categories_named == "all" else categories_named:
                if name not in names:
                    raise ManifestError(path, f"{field}[{index}].categories",
                                        f"'{entry['id']}' names the category '{name}', which the toolbox does not "
                                        f"have (there are: {', '.join(sorted(names))})")
            for block in entry.get("blocks", []):
                if block not in types:
                    raise ManifestError(path, f"{field}[{index}].blocks",
                                        f"'{entry['id']}' names the block '{block}', which is not in the toolbox")


def load_profile(profile_dir: Path, shared_toolboxes: Path, source: str = "folder") -> Profile:
    """Read and validate a whole profile folder; raise ManifestError on the first problem."""
    profile_dir = Path(profile_dir)
    if not (profile_dir / MANIFEST_NAME).is_file():
        raise ManifestError(profile_dir / MANIFEST_NAME, None, "no profile manifest here (profile.yaml is missing)")
    manifest = read_manifest(profile_dir)
    blocks = read_blocks(profile_dir / manifest["blocks"])
    categories = read_toolbox(profile_dir / manifest["toolbox"], shared_toolboxes, {spec.type for spec in blocks})
    own_types, shared_blocks = {spec.type for spec in blocks}, ()
    for definitions in shared_definition_files(categories, shared_toolboxes):
        shared = read_blocks(definitions)
        clash = own_types & {spec.type for spec in shared}
        if clash:
            raise ManifestError(profile_dir / manifest["blocks"], f"blocks[{sorted(clash)[0]}]",
                                f"is also defined by the shared blocks in {definitions.name}")
        shared_blocks += shared
    _check_levels_and_capabilities(profile_dir / MANIFEST_NAME, manifest, categories)
    return Profile(
        id=manifest["id"], name=manifest["name"], version=manifest["version"], root=profile_dir,
        source=source, manifest=manifest, blocks=blocks, toolbox_categories=categories, shared_blocks=shared_blocks,
    )
