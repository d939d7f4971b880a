"""Reading a program file for the editor: the profile it needs and what the editor must do.

The file is read and checked here; whether every block exists is checked by the editor
page itself (it knows Blockly's own blocks), which refuses a program with unknown
blocks before touching the workspace. ``unknown_blocks_error`` words that refusal.

What opening changes without refusing is said, never done silently: a program for a
profile that is not installed is shown with another one (``missing_profile``), and field
values its blocks do not offer are replaced by the page (``replaced_fields``, filled in
from the page's answer). ``opening_warnings`` words both for the command line.
"""
from dataclasses import dataclass, field
from pathlib import Path

from rockly_desktop.core.app_texts import app_local_text, app_text
from rockly_desktop.core.errors import ProgramFileError, UnknownBlocksError
from rockly_desktop.core.program import load_program, read_text_file
from rockly_desktop.core.workspace_blocks import (
    MAX_BLOCK_DEPTH,
    block_depth,
    block_types_in_workspace,
    block_types_in_xml,
    parse_blockly_xml,
    rename_legacy_fields,
    untyped_block_number,
    untyped_xml_block_number,
    xml_block_depth,
    xml_to_text,
)
from rockly_desktop.core.workspace_checks import rounded_numbers, workspace_problem, xml_problem
from rockly_desktop.profiles.profile import Profile
from rockly_desktop.profiles.registry import ProfileRegistry

XML_SUFFIX = ".xml"


@dataclass(frozen=True)
class ProgramToOpen:
    """A program file that was read: the profile to show it with, and its content."""

    path: Path
    profile: Profile
    workspace: dict = None
    xml: str = None
    declared_profile: str = None
    breakpoints: tuple = ()
    missing_profile: str = None  # the declared profile when it is not installed (``profile`` stands in for it)
    installed_profiles: tuple = ()  # then: the installed profile ids
    missing_packs: tuple = ()  # (pack id, version) of the block packs the program records that are not installed
    # What the editor page replaced when it showed the program: one dict per field value it
    # could not keep ({number, id, type, field, requested, now}); set from the page's answer.
    replaced_fields: list = field(default_factory=list, compare=False)
    # Whole numbers too large for the editor to keep exactly, in the same form (known before the page).
    rounded_numbers: tuple = ()
    # A Python program converted to blocks: the (first, last) lines of its text that became Python blocks.
    python_blocks: tuple = ()

    def take_load_result(self, result: dict):
        """Keep what the page says it had to change while loading this program (and the numbers it rounds)."""
        self.replaced_fields[:] = [*self.rounded_numbers, *((result or {}).get("replacedFields") or [])]

    @property
    def block_count(self) -> int:
        """How many blocks the program has (shadows included)."""
        if self.is_import:
            return self.xml.count("<block") + self.xml.count("<shadow")
        return sum(block_types_in_workspace(self.workspace or {}).values())

    @property
    def is_import(self) -> bool:
        """True for a first-Rockly XML program (it becomes an unsaved Rockly program)."""
        return self.xml is not None

    def editor_call(self) -> tuple:
        """The editor page call that shows this program: (name, args)."""
        if self.is_import:
            return "importXml", {"xml": self.xml}
        return "load", {"workspace": self.workspace, "breakpoints": list(self.breakpoints)}


def _best_profile_for(block_types, registry: ProfileRegistry, fallback: Profile) -> Profile:
    """The installed profile defining most of ``block_types`` (the fallback if none does)."""
    scored = [(len(block_types & profile.own_block_types), profile) for profile in registry.profiles.values()]
    best_score, best = max(scored, key=lambda pair: pair[0], default=(0, fallback))
    return best if best_score else fallback


def read_program_to_open(path, registry: ProfileRegistry, fallback: Profile) -> ProgramToOpen:
    """Read a ``.rockly`` or first-Rockly ``.xml`` file; raise ProgramFileError if it is bad.

    The profile is the one the program names, or for XML (and programs of a profile that
    is not installed) the installed one defining most of its blocks, else ``fallback``.
    """
    path = Path(path)
    if path.suffix.lower() == XML_SUFFIX:
        root = parse_blockly_xml(read_text_file(path), path)
        _refuse_too_deep(path, xml_block_depth(root))
        _refuse_untyped(path, untyped_xml_block_number(root))
        _refuse_broken(path, xml_problem(root))
        profile = _best_profile_for(set(block_types_in_xml(root)), registry, fallback)
        rename_legacy_fields(root, profile.legacy_fields)
        return ProgramToOpen(path, profile, xml=xml_to_text(root))
    return program_to_open(path, load_program(path), registry, fallback)


def program_to_open(path, program, registry: ProfileRegistry, fallback: Profile, python_blocks=()) -> ProgramToOpen:
    """A ``core.program.Program`` read from ``path`` (a ``.rockly`` file, or a ``.py`` converted in memory with
    ``python_blocks``: the (first, last) lines that stayed Python) checked as ``read_program_to_open`` checks one."""
    _refuse_too_deep(path, block_depth(program.workspace))
    _refuse_untyped(path, untyped_block_number(program.workspace))
    _refuse_broken(path, workspace_problem(program.workspace))
    if program.profile_id in registry.profiles:
        profile, missing = registry.get(program.profile_id), None
    else:
        profile = _best_profile_for(set(block_types_in_workspace(program.workspace)), registry, fallback)
        missing = program.profile_id
    installed_packs = {pack.id for pack in profile.packs}
    return ProgramToOpen(path, profile, workspace=program.workspace, declared_profile=program.profile_id,
                         breakpoints=tuple(program.breakpoints), missing_profile=missing,
                         installed_profiles=tuple(registry.profiles) if missing else (),
                         missing_packs=tuple((pack_id, version) for pack_id, version in sorted(program.packs.items())
                                             if pack_id not in installed_packs),
                         rounded_numbers=tuple(rounded_numbers(program.workspace)), python_blocks=tuple(python_blocks))


def _refuse_too_deep(path, depth: int):
    if depth > MAX_BLOCK_DEPTH:
        raise ProgramFileError(path, app_local_text("file_too_deep", depth=depth, limit=MAX_BLOCK_DEPTH))


def _refuse_untyped(path, number):
    if number is not None:
        raise ProgramFileError(path, app_local_text("file_broken_no_type", number=number))


def _refuse_broken(path, problem):
    if problem is not None:
        raise ProgramFileError(path, app_local_text("file_broken", problem=problem))


def unknown_blocks_error(program: ProgramToOpen, unknown_types, registry: ProfileRegistry) -> UnknownBlocksError:
    """The error for a program the editor refused because of ``unknown_types``."""
    declared = program.declared_profile
    return UnknownBlocksError(unknown_types, declared, declared in registry.profiles if declared else False,
                              missing_packs=program.missing_packs)


def describe_replaced_field(entry: dict, language: str = "en") -> str:
    """One replaced field value in plain words (in ``language``): which block, which field, what became of it."""
    where = app_text("opening_block", language, number=entry.get("number"), type=entry.get("type"))
    requested, name = entry.get("requested"), entry.get("field")
    if entry.get("missing"):
        return app_text("opening_field_missing", language, where=where, field=name, requested=repr(requested))
    if entry.get("rounded"):
        return app_text("opening_field_rounded", language, where=where, field=name, requested=requested,
                        now=entry.get("now"))
    return app_text("opening_field_replaced", language, where=where, field=name, requested=repr(requested),
                    now=repr(entry.get("now")))


def opening_warnings(program: ProgramToOpen, language: str = "en") -> list:
    """What opening ``program`` changed, in plain words in ``language`` (one line each; empty if nothing)."""
    warnings = []
    if program.missing_profile:
        warnings.append(app_text("opening_missing_profile", language, declared=program.missing_profile,
                                 installed=", ".join(program.installed_profiles), used=program.profile.id))
    warnings.extend(app_text("opening_missing_pack", language, pack=pack_id, version=version)
                    for pack_id, version in program.missing_packs)
    warnings.extend(describe_replaced_field(entry, language) for entry in program.replaced_fields)
    if program.python_blocks:
        lines = ", ".join(str(first) if first == last else f"{first}–{last}" for first, last in program.python_blocks)
        warnings.append(app_text("opening_python_blocks", language, lines=lines))
    return warnings
