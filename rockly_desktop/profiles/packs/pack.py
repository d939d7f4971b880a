"""A block pack folder: its manifest (``pack.yaml``), blocks, toolbox and made blocks, read and checked.

A pack looks like a small robot profile without code::

    packs/my_robot_extras/
      pack.yaml      schema: 1, id, name, version, adds_to: my_robot, languages, blocks, toolbox
      blocks.yaml    Blockly JSON definitions with their ``python`` templates (as a profile's)
      toolbox.yaml   its categories (as a profile's; no shared ones)
      made.yaml      what the maker knows of each block it made (``spec.MadeBlock.to_data``)
      messages/      (``messages: messages``) ROS definitions its blocks need that the robot said (as a
                     profile's ``messages``: <package>/msg|srv|action/*); the profile it joins knows them

Everything but ``made.yaml`` may be edited by hand; ``made.yaml`` only lets the maker show a
block again and ``rockly blocks list`` say what each does.
"""
from dataclasses import dataclass
from pathlib import Path

from rockly_desktop.core import paths
from rockly_desktop.core.errors import ManifestError
from rockly_desktop.core.ros_definitions import DEFINITION_KINDS, definition_problem
from rockly_desktop.profiles.blocks import read_blocks
from rockly_desktop.profiles.i18n import localize
from rockly_desktop.profiles.manifest import MANIFEST_FIELDS, FieldSpec, read_fields
from rockly_desktop.profiles.packs.spec import MadeBlock
from rockly_desktop.profiles.packs.template_check import TemplateRefused, check_template
from rockly_desktop.profiles.toolbox import read_toolbox
from rockly_desktop.profiles.yaml_files import read_yaml_mapping

PACK_MANIFEST = "pack.yaml"
# Blockly's own block families: a pack defining one of them would change what every program's
# loops, numbers and texts do (a profile's and another pack's types are refused when it joins).
BLOCKLY_PREFIXES = ("controls_", "logic_", "math_", "text", "lists_", "variables_", "procedures_", "colour_")
MADE_FILE = "made.yaml"
_SHARED = {spec.name: spec for spec in MANIFEST_FIELDS}
PACK_FIELDS = (
    _SHARED["schema"], _SHARED["id"], _SHARED["name"], _SHARED["version"],
    FieldSpec("adds_to", "identifier", True, "The id of the robot profile whose toolbox the pack adds to."),
    _SHARED["description"], _SHARED["languages"], _SHARED["blocks"], _SHARED["toolbox"], _SHARED["messages"],
)


@dataclass(frozen=True, eq=False)
class Pack:
    """A block pack read from its folder: what it adds to which profile."""

    id: str
    name: object
    version: str
    adds_to: str
    root: Path
    manifest: dict
    blocks: tuple               # BlockSpecs, as a profile's
    toolbox_categories: list    # its own categories, as read_toolbox gives them
    made: tuple = ()            # MadeBlocks of made.yaml

    @property
    def block_types(self) -> set:
        """The block types the pack defines."""
        return {spec.type for spec in self.blocks}

    def display_name(self, language: str = "en") -> str:
        """The pack's name for people, in ``language``."""
        return localize(self.name, language)

    @property
    def message_folder(self):
        """The folder of the pack's ROS definitions (its manifest's ``messages``), or None."""
        folder = self.manifest.get("messages")
        return self.root / folder if folder else None

    def made_block(self, block_id: str):
        """The MadeBlock of ``block_id``, or None (a block written by hand, or not in the pack)."""
        return next((block for block in self.made if block.id == block_id), None)


def user_packs_dir() -> Path:
    """Where the user's block packs live (``$XDG_DATA_HOME/rockly/packs``)."""
    return paths.user_packs_dir()


def is_pack_folder(folder) -> bool:
    """True when ``folder`` holds a pack manifest."""
    return (Path(folder) / PACK_MANIFEST).is_file()


def read_pack_manifest(folder: Path) -> dict:
    """Read and check ``pack.yaml``; raise ManifestError on the first problem."""
    return read_fields(folder / PACK_MANIFEST, PACK_FIELDS, folder)


def _read_made(folder: Path) -> tuple:
    path = folder / MADE_FILE
    if not path.is_file():
        return ()
    raw = read_yaml_mapping(path).get("blocks", [])
    if not isinstance(raw, list):
        raise ManifestError(path, "blocks", "must be a list of made blocks")
    made = []
    for index, data in enumerate(raw):
        try:
            made.append(MadeBlock.from_data(data))
        except (TypeError, ValueError) as error:
            raise ManifestError(path, f"blocks[{index}]", f"is no made block ({error})") from None
    return tuple(made)


def check_definitions(folder: Path) -> None:
    """Raise ManifestError naming the first definition file in ``folder`` (``<package>/msg|srv|action/``) that
    cannot be read, or a file there that is no definition of its folder's kind."""
    for path in sorted(folder.glob("*/*/*")):
        kind = path.parent.name
        if kind not in DEFINITION_KINDS or path.suffix != f".{kind}" or not path.is_file():
            raise ManifestError(path, None, "is no ROS definition (those are <package>/msg|srv|action/NAME.KIND)")
        try:
            problem = definition_problem(path.read_text(encoding="utf-8"), kind)
        except (OSError, UnicodeDecodeError) as error:
            problem = f"cannot be read ({error})"
        if problem is not None:
            raise ManifestError(path, None, problem)


def check_pack_blocks(path: Path, blocks) -> None:
    """Raise ManifestError for the first block of a pack's block file (``path``) that redefines one of
    Blockly's own block types or whose template does more than call Rockly's commands (``template_check``)."""
    for index, spec in enumerate(blocks):
        if spec.type.startswith(BLOCKLY_PREFIXES):
            raise ManifestError(path, f"blocks[{index}].type", f"'{spec.type}' is one of Blockly's own block "
                                                               f"types (or named like them); a pack adds new ones")
        try:
            check_template(spec.code, spec.slots, spec.handlers)
        except TemplateRefused as refusal:
            raise ManifestError(path, f"blocks[{index}].python.code", str(refusal)) from None


def load_pack(folder, shared_toolboxes: Path = None) -> Pack:
    """Read and check a whole pack folder; raise ManifestError on the first problem."""
    folder = Path(folder)
    if not is_pack_folder(folder):
        raise ManifestError(folder / PACK_MANIFEST, None, "no block pack manifest here (pack.yaml is missing)")
    manifest = read_pack_manifest(folder)
    blocks = read_blocks(folder / manifest["blocks"])
    check_pack_blocks(folder / manifest["blocks"], blocks)
    toolbox_path = folder / manifest["toolbox"]
    categories = read_toolbox(toolbox_path, shared_toolboxes or paths.shared_toolboxes_dir(),
                              {spec.type for spec in blocks})
    for index, category in enumerate(categories):
        if "shared" in category:
            raise ManifestError(toolbox_path, f"categories[{index}].shared",
                                "a block pack adds its own categories only (the profile brings the shared ones)")
    if manifest.get("messages"):
        check_definitions(folder / manifest["messages"])
    return Pack(manifest["id"], manifest["name"], manifest["version"], manifest["adds_to"], folder, manifest,
                blocks, categories, _read_made(folder))


def discover_packs(folder=None) -> tuple:
    """``(packs by id, errors)`` of the pack folders in ``folder`` (default: the user's); a
    broken pack is an error and is skipped, as a broken profile is."""
    folder = Path(folder) if folder is not None else user_packs_dir()
    packs, errors = {}, []
    if not folder.is_dir():
        return packs, errors
    for child in sorted(folder.iterdir()):
        if child.name.startswith(".") or not child.is_dir() or not is_pack_folder(child):
            continue  # a hidden folder is a write in progress (see making.py)
        try:
            pack = load_pack(child)
        except ManifestError as error:
            errors.append(error)
            continue
        if pack.id in packs:
            errors.append(ManifestError(child / PACK_MANIFEST, "id", f"'{pack.id}' is already provided by "
                                                                     f"{packs[pack.id].root}; this copy is ignored"))
            continue
        packs[pack.id] = pack
    return packs, errors
