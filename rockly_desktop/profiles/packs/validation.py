"""What is wrong with a made block, in words of Rockly's catalogue (the reader's language).

``block_problems`` lists every problem (empty: the block can be made); ``check_block`` raises
them as one ``BlockMakerError``. The maker's dialog shows ``problems`` as they are typed.
"""
import math
import re

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.profiles.packs.interfaces import fields_of_block_kind, interface_fields, knows_type
from rockly_desktop.profiles.packs.spec import (
    COMPARISONS,
    INTERFACE_KINDS,
    KINDS,
    OUTCOME,
    VALUE_KINDS,
    MadeBlock,
)

IDENTIFIER = re.compile(r"^[a-z][a-z0-9_]{0,39}$")
_COLOUR = re.compile(r"^#[0-9a-fA-F]{6}$")
_PLACE = re.compile(r"%(\d+)")
_MAX_INPUTS = {"sensor_value": 0, "get_param": 0, "wait_until": 1, "set_param": 1}


class BlockMakerError(RocklyError):
    """A block or pack cannot be made, imported or read: one or more texts of the catalogue."""

    def __init__(self, problems):
        self.problems = list(problems) if isinstance(problems, (list, tuple)) else [problems]
        super().__init__("; ".join(str(problem) for problem in self.problems))

    def in_language(self, language: str) -> str:
        """Every problem in ``language``, joined by '; '."""
        return "; ".join(problem.in_language(language) if hasattr(problem, "in_language") else str(problem)
                         for problem in self.problems)


def sentence_places(sentence: str) -> list:
    """The numbers of the ``%n`` places in ``sentence``, in order."""
    return [int(number) for number in _PLACE.findall(sentence or "")]


def block_problems(block: MadeBlock, profile, pack=None) -> list:
    """Every problem of ``block`` as LocalTexts: its id against ``profile`` (with its installed
    packs) and ``pack`` (the pack it goes into, None for a new one; a block of the same id in it
    is refused too: replace it explicitly), its kind, interface, fields, inputs, sentence and looks."""
    problems = _id_problems(block, profile, pack)
    if block.kind not in KINDS:
        return problems + [app_local_text("pack_kind_unknown", kind=block.kind, kinds=", ".join(KINDS))]
    if not str(block.interface or "").strip():
        problems.append(app_local_text("pack_interface_missing"))
    problems += _type_problems(block, profile)
    problems += _input_problems(block, profile)
    problems += _sentence_problems(block)
    if not _COLOUR.fullmatch(str(block.colour or "")):
        problems.append(app_local_text("pack_colour_bad", colour=block.colour))
    problems += _unwritable_texts(block)
    if not any(str(name).strip() for name in (block.category or {}).values()):
        problems.append(app_local_text("pack_category_missing"))
    return problems


def check_block(block: MadeBlock, profile, pack=None) -> None:
    """Raise a BlockMakerError with every problem of ``block`` (see ``block_problems``)."""
    problems = block_problems(block, profile, pack)
    if problems:
        raise BlockMakerError(problems)


def _id_problems(block, profile, pack) -> list:
    if not isinstance(block.id, str) or not IDENTIFIER.fullmatch(block.id):
        return [app_local_text("pack_block_id_bad", id=block.id)]
    own_pack = pack.id if pack is not None else None
    owner = profile.pack_of(block.id)
    if pack is not None and block.id in pack.block_types:
        return [app_local_text("pack_block_id_in_pack", pack=pack.id, id=block.id)]
    if owner is not None and owner != own_pack:
        return [app_local_text("pack_block_id_in_pack", pack=owner, id=block.id)]
    if owner is None and block.id in profile.block_types:
        return [app_local_text("pack_block_id_in_profile", profile=profile.id, id=block.id)]
    return []


def _type_problems(block, profile) -> list:
    kind = INTERFACE_KINDS.get(block.kind)
    if kind is None:
        return []
    if not str(block.interface_type or "").strip():
        return [app_local_text("pack_type_missing", interface=block.interface or "?")]
    if not knows_type(profile, block.interface_type, kind):
        return [app_local_text("pack_type_unknown", type=block.interface_type)]
    kinds = {entry.path: entry.kind for entry in fields_of_block_kind(profile, block.kind, block.interface_type)}
    fields = set(kinds)
    problems = []
    named = [entry.field for entry in block.inputs if entry.field] + list(block.fixed)
    if block.kind in ("sensor_value", "wait_until"):
        if not block.read_field:
            problems.append(app_local_text("pack_read_field_missing"))
        else:
            named.append(block.read_field)
    for path in dict.fromkeys(named):
        if path not in fields:
            problems.append(_unknown_field(block.interface_type, path, fields))
    for entry in block.inputs:
        path = entry.field or (block.read_field if block.kind == "wait_until" else "")
        if path in kinds and entry.kind in VALUE_KINDS and kinds[path] != entry.kind:
            problems.append(app_local_text("pack_input_field_kind", name=entry.name, field=path,
                                           kind=app_local_text(f"pack_kind_{entry.kind}"),
                                           needed=_kind_text(kinds[path])))
    filled = [entry.field for entry in block.inputs if entry.field] + list(block.fixed)
    for path in sorted({path for path in filled if filled.count(path) > 1}):
        problems.append(app_local_text("pack_field_twice", field=path))
    if block.kind == "call_service" and block.result:
        response = {entry.path for entry in interface_fields(profile, block.interface_type, "srv", "out")}
        if block.result not in response:
            problems.append(_unknown_field(block.interface_type, block.result, response))
    if block.kind == "send_goal" and block.result not in ("", OUTCOME):
        problems.append(app_local_text("pack_result_bad", result=block.result))
    return problems


def _kind_text(kind):
    """A field's kind in words (number, text, yes_no, list or messages)."""
    return app_local_text(f"pack_kind_{kind}")


def _unknown_field(type_name, path, fields):
    return app_local_text("pack_field_unknown", type=type_name, field=path, fields=", ".join(sorted(fields)) or "-")


def _input_problems(block, profile) -> list:
    problems, seen = [], set()
    limit = _MAX_INPUTS.get(block.kind)
    if limit is not None and len(block.inputs) > limit:
        problems.append(app_local_text("pack_too_many_inputs", kind=block.kind, count=limit, given=len(block.inputs)))
    for entry in block.inputs:
        if not isinstance(entry.name, str) or not IDENTIFIER.fullmatch(entry.name):
            problems.append(app_local_text("pack_input_name_bad", name=entry.name))
        elif entry.name in seen:
            problems.append(app_local_text("pack_input_twice", name=entry.name))
        seen.add(entry.name)
        if entry.kind not in VALUE_KINDS:
            problems.append(app_local_text("pack_input_kind_bad", name=entry.name, kind=entry.kind))
            continue
        if INTERFACE_KINDS.get(block.kind) and block.kind != "wait_until" and not entry.field:
            problems.append(app_local_text("pack_input_needs_field", name=entry.name))
        problems += _range_problems(entry)
    if block.kind == "sensor_value" and block.value_kind not in VALUE_KINDS:
        problems.append(app_local_text("pack_value_kind_bad", kind=block.value_kind))
    if block.kind == "wait_until":
        if block.comparison not in COMPARISONS:
            problems.append(app_local_text("pack_comparison_bad", comparison=block.comparison,
                                           comparisons=", ".join(COMPARISONS)))
        if not block.inputs and block.target is None:
            problems.append(app_local_text("pack_target_missing"))
    return problems


def _range_problems(entry) -> list:
    low, high = entry.minimum, entry.maximum
    not_numbers = [bound for bound in (low, high) if bound is not None and not _is_number(bound)]
    if not_numbers:  # a bound typed as no number ("2,5" in English) is said, not dropped
        return [app_local_text("pack_input_bound_bad", name=entry.name, bound=not_numbers[0])]
    if entry.kind == "number":
        if low is not None and high is not None and low > high:
            return [app_local_text("pack_input_range_bad", name=entry.name, minimum=low, maximum=high)]
        default = entry.default
        fits = default is None or (_is_number(default) and (low is None or default >= low)
                                   and (high is None or default <= high))
    else:
        fits = entry.default is None or isinstance(entry.default, {"text": str, "yes_no": bool}[entry.kind])
    if fits:
        return []
    return [app_local_text("pack_input_default_bad", name=entry.name, default=repr(entry.default),
                           kind=app_local_text(f"pack_kind_{entry.kind}"),
                           minimum="-" if low is None else low, maximum="-" if high is None else high)]


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _texts_of(value):
    """Every text in ``value`` (a text, or mappings and lists holding texts)."""
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for item in value.values():
            yield from _texts_of(item)
    elif isinstance(value, (list, tuple)):
        for item in value:
            yield from _texts_of(item)


def _unwritable_texts(block) -> list:
    """A text with half a character (a lone surrogate: bytes a command line could not decode) cannot go into
    a UTF-8 file; said instead of failing half-way through the write."""
    texts = _texts_of([block.sentence, block.tooltip, block.category, block.fixed, block.interface,
                       [entry.default for entry in block.inputs]])
    broken = [text for text in texts if any("\ud800" <= char <= "\udfff" for char in text)]
    return [app_local_text("pack_text_broken", text=broken[0].encode("utf-8", "backslashreplace").decode("ascii"))
            ] if broken else []


def _sentence_problems(block) -> list:
    sentences = {language: text for language, text in (block.sentence or {}).items() if str(text or "").strip()}
    if not sentences:
        return [app_local_text("pack_sentence_missing")]
    wanted = list(range(1, len(block.inputs) + 1))
    return [app_local_text("pack_sentence_places", sentence=text, count=len(block.inputs),
                           found=", ".join(f"%{number}" for number in sentence_places(text)) or "-")
            for text in sentences.values() if sorted(sentence_places(text)) != wanted]
