"""A profile's block file: Blockly JSON definitions, each with its Python as a template.

A block's Python is data, for example::

    python:
      code: "robot.drive({speed}, {direction})"
      values: {direction: {"+": forward, "-": backward}}
      defaults: {speed: 0}

``{name}`` is replaced by the field ``name`` rendered as a safely quoted Python literal
(after mapping through ``values``), by the value input ``name`` as a sub-expression
(``defaults`` when empty, else ``None``), or by the statement input ``name`` as an
indented body. The editor page turns these templates into Blockly generators.

Two things the editor adds for ROS-shaped blocks:

- ``mutator: rockly_typed_fields`` on a block with a dropdown named ``message_type``,
  ``service_type`` or ``action_type``: the dropdown lists the ROS types the editor knows
  (messages, service requests or action goals), the block grows one checked input per
  field of the chosen type, and ``{fields}`` in the template becomes those fields as a
  Python dict (inputs left empty keep the type's defaults).
- ``handlers: {input: variable_field}``: a statement input that runs as a function the
  command calls with one argument (for example each feedback of an action goal), which
  the handler's blocks read from the named variable field. ``{input}`` becomes the
  function's name, or ``None`` when the input is empty.
"""
import re
import string
from dataclasses import dataclass, field
from pathlib import Path

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.i18n import localize
from rockly_desktop.profiles.yaml_files import read_yaml_mapping

_BLOCK_TYPE = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_FIELD_ARGS = {"field_dropdown", "field_input", "field_number", "field_checkbox", "field_angle",
               "field_colour", "field_multilinetext", "field_variable", "field_label_serializable"}
_INPUT_KINDS = {"input_value": "value", "input_statement": "statement"}
TYPED_FIELDS_MUTATOR = "rockly_typed_fields"
TYPE_DROPDOWNS = ("message_type", "service_type", "action_type")


@dataclass(frozen=True)
class BlockSpec:
    """One block: its Blockly definition (texts may be per language) and its Python template."""

    type: str
    definition: dict
    code: str
    values: dict = field(default_factory=dict)
    defaults: dict = field(default_factory=dict)
    slots: dict = field(default_factory=dict)
    handlers: dict = field(default_factory=dict)

    @property
    def is_expression(self) -> bool:
        """True when the block plugs into an input (it has an output) instead of stacking."""
        return "output" in self.definition

    def editor_config(self, language: str, catalogues=()) -> dict:
        """What the editor page needs: the localized definition (see ``i18n.localize`` for
        ``catalogues``) and the generator template."""
        return {
            "definition": localize(self.definition, language, catalogues),
            "python": {"code": self.code, "values": self.values, "defaults": self.defaults,
                       "slots": self.slots, "handlers": self.handlers, "expression": self.is_expression},
        }


def _slots_of(definition: dict) -> dict:
    """Map each named field/input of a definition to 'field', 'value' or 'statement'."""
    slots = {}
    for key, args in definition.items():
        if not (key.startswith("args") and isinstance(args, list)):
            continue
        for arg in args:
            if not isinstance(arg, dict) or "name" not in arg:
                continue
            kind = arg.get("type")
            if kind in _INPUT_KINDS:
                slots[arg["name"]] = _INPUT_KINDS[kind]
            elif kind in _FIELD_ARGS or (isinstance(kind, str) and kind.startswith("field_")):
                slots[arg["name"]] = "field"
    return slots


def _field_kinds(definition: dict) -> dict:
    """Map each named field of a definition to its Blockly field type."""
    return {arg["name"]: arg.get("type") for key, args in definition.items()
            if key.startswith("args") and isinstance(args, list)
            for arg in args if isinstance(arg, dict) and "name" in arg}


def _typed_fields_slots(definition: dict, where: str, path: Path) -> dict:
    """The extra ``fields`` slot of a block with the typed-fields mutator (checked)."""
    mutator = definition.get("mutator")
    if mutator is None:
        return {}
    if mutator != TYPED_FIELDS_MUTATOR:
        raise ManifestError(path, f"{where}.mutator", f"'{mutator}' is not a mutator Rockly's editor has "
                                                      f"(it has: {TYPED_FIELDS_MUTATOR})")
    kinds = _field_kinds(definition)
    dropdowns = [name for name in TYPE_DROPDOWNS if kinds.get(name) == "field_dropdown"]
    if len(dropdowns) != 1:
        raise ManifestError(path, f"{where}.mutator", f"{TYPED_FIELDS_MUTATOR} needs exactly one field_dropdown "
                                                      f"named one of {list(TYPE_DROPDOWNS)}")
    if "fields" in kinds:
        raise ManifestError(path, f"{where}.mutator", f"{TYPED_FIELDS_MUTATOR} adds the slot 'fields'; "
                                                      "the block may not have its own field or input of that name")
    return {"fields": "typed_fields"}


def _checked_handlers(python: dict, slots: dict, kinds: dict, where: str, path: Path) -> dict:
    handlers = python.get("handlers", {})
    if not isinstance(handlers, dict):
        raise ManifestError(path, f"{where}.python.handlers", "must map statement inputs to a variable field")
    for name, variable in handlers.items():
        if slots.get(name) != "statement":
            raise ManifestError(path, f"{where}.python.handlers.{name}", "names no statement input of this block")
        if kinds.get(variable) != "field_variable":
            raise ManifestError(path, f"{where}.python.handlers.{name}",
                                f"'{variable}' is no field_variable of this block (the handler's argument goes there)")
    return handlers


def _placeholders(code: str, where: str, path: Path) -> set:
    """The ``{name}`` placeholders of a template; only plain names (what the page fills in)."""
    try:
        parts = [(name, spec, conversion) for _, name, spec, conversion in string.Formatter().parse(code)
                 if name is not None]
    except ValueError as error:
        raise ManifestError(path, where, f"the template is broken ({error}); "
                                         "write a literal brace as '{{' or '}}'") from None
    for name, spec, conversion in parts:
        if spec or conversion or not name.isidentifier():
            written = f"{{{name}{'!' + conversion if conversion else ''}{':' + spec if spec else ''}}}"
            raise ManifestError(path, where, f"placeholders are plain names like {{speed}}; '{written}' is not one")
    return {name for name, _, _ in parts}


def _parse_block(raw, index: int, path: Path) -> BlockSpec:
    where = f"blocks[{index}]"
    if not isinstance(raw, dict):
        raise ManifestError(path, where, "must be a mapping with 'type', 'message0' and 'python'")
    block_type = raw.get("type")
    if not isinstance(block_type, str) or not _BLOCK_TYPE.fullmatch(block_type):
        raise ManifestError(path, f"{where}.type", "must be a block type name (letters, digits, '_')")
    where = f"blocks[{block_type}]"
    if "message0" not in raw:
        raise ManifestError(path, f"{where}.message0", "is missing: the text shown on the block")
    python = raw.get("python")
    if isinstance(python, str):
        python = {"code": python}
    if not isinstance(python, dict) or not isinstance(python.get("code"), str) or not python["code"].strip():
        raise ManifestError(path, f"{where}.python", "is missing: the Python the block becomes ('code: ...')")
    unknown_keys = set(python) - {"code", "values", "defaults", "handlers"}
    if unknown_keys:
        raise ManifestError(path, f"{where}.python",
                            f"unknown key(s) {sorted(unknown_keys)} (use code, values, defaults, handlers)")
    definition = {key: value for key, value in raw.items() if key != "python"}
    slots = {**_slots_of(definition), **_typed_fields_slots(definition, where, path)}
    handlers = _checked_handlers(python, slots, _field_kinds(definition), where, path)
    for name in sorted(_placeholders(python["code"], f"{where}.python.code", path)):
        if name not in slots:
            raise ManifestError(path, f"{where}.python.code",
                                f"uses {{{name}}}, but the block has no field or input named '{name}' "
                                f"(it has: {sorted(slots) or 'none'})")
    values = python.get("values", {})
    if not isinstance(values, dict):
        raise ManifestError(path, f"{where}.python.values", "must map field names to {value: Python value}")
    for name, mapping in values.items():
        if slots.get(name) != "field" or not isinstance(mapping, dict):
            raise ManifestError(path, f"{where}.python.values.{name}", "must map the values of a field of this block")
    defaults = python.get("defaults", {})
    if not isinstance(defaults, dict):
        raise ManifestError(path, f"{where}.python.defaults",
                            "must map value input names to the Python used when they are empty")
    for name in defaults:
        if slots.get(name) != "value":
            raise ManifestError(path, f"{where}.python.defaults.{name}", "names no value input of this block")
    return BlockSpec(block_type, definition, python["code"], values, defaults, slots, handlers)


def block_spec(raw: dict, path: Path, index: int = 0) -> BlockSpec:
    """One block definition (a ``blocks.yaml`` entry) read and checked as ``read_blocks`` does;
    ManifestError naming ``path`` when it is wrong."""
    return _parse_block(raw, index, path)


def read_blocks(path: Path) -> tuple:
    """Read and validate a profile's block file; return its BlockSpecs in file order."""
    data = read_yaml_mapping(path)
    raw_blocks = data.get("blocks")
    if not isinstance(raw_blocks, list) or not raw_blocks:
        raise ManifestError(path, "blocks", "must be a non-empty list of block definitions")
    specs, seen = [], set()
    for index, raw in enumerate(raw_blocks):
        spec = _parse_block(raw, index, path)
        if spec.type in seen:
            raise ManifestError(path, f"blocks[{spec.type}]", "is defined twice")
        seen.add(spec.type)
        specs.append(spec)
    return tuple(specs)
