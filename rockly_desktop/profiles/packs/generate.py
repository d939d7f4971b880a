"""A made block as an ordinary block definition (Blockly JSON plus its Python template) and
toolbox entry, as a profile's ``blocks.yaml`` and ``toolbox.yaml`` hold them.

The Python calls only the generic ``ros`` commands, so what a made block sends passes the
same limits, safe stop, recording and stepping as every other block. ``python_preview``
shows the Python a new block becomes (every input at its default), for the maker's preview.
"""
import string

from rockly_desktop.core.app_texts import app_catalogue, app_text, languages
from rockly_desktop.profiles.packs.spec import BLOCKLY_CHECKS, COMPARISONS, OUTCOME, MadeBlock

WAIT_STEP = 0.1  # seconds between looks at a topic while waiting until a field is something
_SHADOWS = {"number": ("math_number", "NUM", 0), "text": ("text", "TEXT", ""),
            "yes_no": ("logic_boolean", "BOOL", False)}


def texts_in_languages(texts: dict) -> dict:
    """A text given in some languages as ``{en: ..., de: ...}`` with English present (the other
    language's text where English is missing), or a plain string when only one is given."""
    given = {language: str(text) for language, text in (texts or {}).items() if str(text or "").strip()}
    if not given:
        return {}
    english = given.get("en") or next(iter(given.values()))
    return {"en": english, **{language: text for language, text in given.items() if language != "en"}}


def _text(texts: dict):
    """``texts`` as a block file writes a text: a plain string for English only, else per language."""
    localized = texts_in_languages(texts)
    return localized["en"] if set(localized) == {"en"} else localized


def _literal(value) -> str:
    """``value`` as Python source in a template (braces doubled, as templates write them)."""
    return repr(value).replace("{", "{{").replace("}", "}}")


def _nested(entries: dict) -> dict:
    """``{"linear.x": code}`` as ``{"linear": {"x": code}}``."""
    tree = {}
    for path, code in entries.items():
        *parents, leaf = path.split(".")
        node = tree
        for name in parents:
            node = node.setdefault(name, {})
        node[leaf] = code
    return tree


def _dict_code(tree: dict) -> str:
    """A nested dict of code pieces as a Python dict display, inside a template."""
    items = ", ".join(f"{_literal(key)}: {_dict_code(value) if isinstance(value, dict) else value}"
                      for key, value in tree.items())
    return "{{" + items + "}}"


def _input_code(entry) -> str:
    """An input's placeholder, held to its bounds (``ros.number_in``) when it has any."""
    placeholder = "{" + entry.name + "}"
    if entry.kind != "number" or (entry.minimum is None and entry.maximum is None):
        return placeholder
    return f"ros.number_in({placeholder}, {_literal(entry.minimum)}, {_literal(entry.maximum)}, {_literal(entry.name)})"


def _fields_code(block: MadeBlock) -> str:
    entries = {path: _literal(value) for path, value in block.fixed.items() if value is not None}  # None: its default
    entries.update({entry.field: _input_code(entry) for entry in block.inputs if entry.field})
    return _dict_code(_nested(entries))


def python_template(block: MadeBlock) -> str:
    """The block's Python template: ``{name}`` for each input, ``{while_waiting}`` for the handler."""
    name, type_name = _literal(block.interface), _literal(block.interface_type)
    kind = block.kind
    if kind == "publish":
        return f"ros.publish_message({name}, {type_name}, {_fields_code(block)})"
    if kind == "call_service":
        call = f"ros.call_service({name}, {type_name}, {_fields_code(block)})"
        return f"ros.field({call}, {_literal(block.result)})" if block.result else call
    if kind == "send_goal":
        handler = ", while_waiting={while_waiting}" if block.while_waiting else ""
        return f"ros.send_goal({name}, {type_name}, {_fields_code(block)}{handler})"
    if kind == "sensor_value":
        return f"ros.latest({name}, {_literal(block.read_field)})"
    if kind == "wait_until":
        target = _input_code(block.inputs[0]) if block.inputs else _literal(block.target)
        return (f"while not ros.latest({name}, {_literal(block.read_field)}) {COMPARISONS[block.comparison]} "
                f"{target}:\n  ros.wait({WAIT_STEP})")
    if kind == "get_param":
        return f"ros.get_param({name})"
    return f"ros.set_param({name}, {_input_code(block.inputs[0]) if block.inputs else 'None'})"


def _tooltip(block: MadeBlock) -> dict:
    """The person's tooltip, with one line per input: its kind, unit and range, in every language."""
    tooltip = texts_in_languages(block.tooltip)
    result = {}
    for language in languages():
        lines = [tooltip.get(language) or tooltip.get("en") or ""]
        for entry in block.inputs:
            bounded = entry.kind == "number" and (entry.minimum is not None or entry.maximum is not None)
            lines.append(app_text(
                "pack_tooltip_input", language, name=entry.name, kind=app_text(f"pack_kind_{entry.kind}", language),
                unit=f" ({entry.unit})" if entry.unit else "",
                range=app_text("pack_tooltip_range", language, minimum="-" if entry.minimum is None else entry.minimum,
                               maximum="-" if entry.maximum is None else entry.maximum) if bounded else ""))
        result[language] = "\n".join(line for line in lines if line)
    return result


def block_definition(block: MadeBlock) -> dict:
    """The block's entry in ``blocks.yaml``: Blockly JSON with ``python`` (code and defaults)."""
    definition = {"type": block.id, "message0": _text(block.sentence)}
    if block.inputs:
        definition["args0"] = [{"type": "input_value", "name": entry.name, "check": BLOCKLY_CHECKS[entry.kind]}
                               for entry in block.inputs]
        definition["inputsInline"] = True
    python = {"code": python_template(block)}
    if block.kind == "send_goal" and block.while_waiting:
        definition.update({
            "message1": _catalogue_text("pack_while_waiting"),
            "args1": [{"type": "field_variable", "name": "feedback", "variable": "feedback"}],
            "message2": _catalogue_text("pack_and_do"),
            "args2": [{"type": "input_statement", "name": "while_waiting"}],
            "inputsInline": False,
        })
        python["handlers"] = {"while_waiting": "feedback"}
    if block.is_expression:
        definition["output"] = _output_check(block)
    else:
        definition.update(previousStatement=None, nextStatement=None)
    definition["colour"] = block.colour
    tooltip = _tooltip(block)
    if any(tooltip.values()):
        definition["tooltip"] = tooltip
    defaults = {entry.name: entry.default for entry in block.inputs if entry.default is not None}
    if defaults:
        python["defaults"] = defaults
    definition["python"] = python
    return definition


def _output_check(block: MadeBlock):
    if block.kind == "sensor_value":
        return BLOCKLY_CHECKS[block.value_kind]
    if block.kind == "send_goal" and block.result == OUTCOME:
        return "String"
    return None


def _catalogue_text(key: str) -> dict:
    return {language: app_catalogue().template(key, language) for language in languages()}


def toolbox_entry(block: MadeBlock) -> dict:
    """The block's entry in a toolbox category: its inputs' defaults as shadow blocks a child types over."""
    inputs = {}
    for entry in block.inputs:
        shadow_type, field, start = _SHADOWS[entry.kind]
        value = start if entry.default is None else entry.default
        if entry.kind == "yes_no":
            value = "TRUE" if value else "FALSE"
        inputs[entry.name] = {"shadow": {"type": shadow_type, "fields": {field: value}}}
    return {"type": block.id, "inputs": inputs} if inputs else {"type": block.id}


def python_preview(block: MadeBlock) -> str:
    """The Python a new block becomes, every input at its default (without one, the value its toolbox
    entry's shadow starts with: ``''``, ``0``, ``False``)."""
    defaults = {entry.name: repr(entry.default if entry.default is not None else _SHADOWS[entry.kind][2])
                for entry in block.inputs}
    defaults["while_waiting"] = "None"
    return string.Formatter().vformat(python_template(block), (), defaults)
