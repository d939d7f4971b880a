"""``rockly blocks ...``: made blocks and block packs on the command line (issue 22).

    rockly blocks make --profile my_robot --pack my_pack --id drive_at --kind publish \\
        --interface /cmd_vel --type geometry_msgs/Twist --input speed=linear.x --range speed=0:0.3 \\
        --default speed=0.1 --unit speed=m/s --fixed angular.z=0 \\
        --sentence-en "drive at %1 m/s" --sentence-de "fahre mit %1 m/s" --colour "#4c97ff" \\
        --category-en "My blocks" --category-de "Meine Blöcke"
        [--backend ros1 --master http://robot:11311]   (a type Rockly does not know is learnt from that robot)
    rockly blocks list [PACK]
    rockly blocks export PACK -o FILE.zip
    rockly blocks import FILE.zip [--replace]

Messages are in ``language`` (Rockly's catalogue); a problem exits with 1 and writes nothing.
"""
import sys

import yaml

from rockly_desktop.core.app_texts import app_local_text, app_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.ros_definitions import learn_definition
from rockly_desktop.core.yaml_nesting import too_deep
from rockly_desktop.profiles.packs.archive import export_pack, import_pack
from rockly_desktop.profiles.packs.interfaces import fields_of_block_kind, knows_type
from rockly_desktop.profiles.packs.making import save_block
from rockly_desktop.profiles.packs.spec import INTERFACE_KINDS, KINDS, BlockInput, MadeBlock
from rockly_desktop.profiles.packs.validation import BlockMakerError
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.robot import links
from rockly_desktop.runtime.options import add_connection_options, connection


def add_blocks_parser(commands, language_option) -> None:
    """The ``blocks`` command and its subcommands, on ``commands`` (argparse subparsers)."""
    blocks = commands.add_parser("blocks", help="blocks made without code, and block packs")
    actions = blocks.add_subparsers(dest="blocks_command", required=True)
    make = actions.add_parser("make", help="make a block into a block pack (the pack is made if new)")
    make.add_argument("--profile", required=True, help="the robot profile the pack adds to, e.g. my_robot")
    make.add_argument("--pack", required=True, help="the block pack's id, e.g. my_robot_extras")
    make.add_argument("--pack-name", help="the pack's name for people (a new pack; default: its id)")
    make.add_argument("--id", required=True, help="the block's id (its type in programs)")
    make.add_argument("--kind", required=True, choices=KINDS, help="what the block does")
    make.add_argument("--interface", required=True, help="the topic, service, action or parameter name")
    make.add_argument("--type", default="", help="its ROS type, e.g. geometry_msgs/Twist (not for parameters)")
    make.add_argument("--input", action="append", default=[], metavar="NAME[=FIELD][:KIND]",
                      help="an input, in %%1..%%n order: the field it fills (its kind comes from the field), "
                           "or for wait_until/set_param its kind (number, text, yes_no)")
    for option, meta, what in (("--unit", "NAME=UNIT", "an input's unit"),
                               ("--default", "NAME=VALUE", "an input's default"),
                               ("--range", "NAME=MIN:MAX", "a number input's bounds (either may be empty)"),
                               ("--fixed", "FIELD=VALUE", "a field always sent with this value (empty: its default)")):
        make.add_argument(option, action="append", default=[], metavar=meta, help=what + " (repeatable)")
    make.add_argument("--read-field", default="", help="sensor_value/wait_until: the field read")
    make.add_argument("--value-kind", default="number", help="sensor_value: number, text or yes_no")
    make.add_argument("--comparison", default="equal", help="wait_until: equal, not_equal, below, above, ...")
    make.add_argument("--target", help="wait_until without an input: the value waited for")
    make.add_argument("--result", default="",
                      help="call_service: the response field the block gives; send_goal: outcome")
    make.add_argument("--while-waiting", action="store_true", help="send_goal: a 'while waiting' part")
    for part in ("sentence", "category", "tooltip"):
        for lang in ("en", "de"):
            make.add_argument(f"--{part}-{lang}", default="", help=f"the block's {part} in {lang}")
    make.add_argument("--colour", default="", help="the block's colour, #rrggbb (the profile's categories' colours)")
    make.add_argument("--replace", action="store_true", help="replace a block of the same id in the pack")
    kinds = links.link_kinds()
    make.add_argument("--backend", choices=[entry.kind for entry in kinds],
                      help="the robot to learn a --type Rockly has no definition for from (kept in the pack), "
                           "with its connection options, as for rockly run")
    add_connection_options(make, kinds)
    language_option(make)
    listing = actions.add_parser("list", help="list the blocks of a block pack (without PACK: the installed packs)")
    listing.add_argument("pack", nargs="?")
    language_option(listing)
    export = actions.add_parser("export", help="write a block pack to one zip file")
    export.add_argument("pack")
    export.add_argument("-o", "--output", required=True, help="the .zip file to write")
    language_option(export)
    importing = actions.add_parser("import", help="install a block pack from its zip file")
    importing.add_argument("file")
    importing.add_argument("--replace", action="store_true", help="replace an installed pack of the same id")
    language_option(importing)


def run_blocks_command(args, language: str) -> int:
    """Run ``rockly blocks ...``; the exit status."""
    registry = ProfileRegistry.discover()
    try:
        if args.blocks_command == "make":
            return _make(args, registry, language)
        if args.blocks_command == "list":
            return _list(_pack(registry, args.pack), language) if args.pack else _list_packs(registry, language)
        if args.blocks_command == "export":
            pack = _pack(registry, args.pack)
            path = export_pack(pack, args.output)
            print(app_text("pack_exported", language, pack=pack.id, version=pack.version, path=path))
            return 0
        pack = import_pack(args.file, registry.base_profiles, replace=args.replace)
        print(app_text("pack_imported", language, pack=pack.id, version=pack.version, profile=pack.adds_to,
                       path=pack.root))
        return 0
    except (RocklyError, OSError) as error:
        text = error.in_language(language) if isinstance(error, RocklyError) else str(error)
        print(f"rockly blocks {args.blocks_command}: {text}", file=sys.stderr)
        return 1


def _pack(registry, pack_id):
    if pack_id in registry.packs:
        return registry.pack(pack_id)
    broken = [error for error in registry.pack_errors if f"/{pack_id}/" in str(error) or f"'{pack_id}'" in str(error)]
    if broken:
        raise broken[0]
    raise BlockMakerError(app_local_text("pack_not_installed", pack=pack_id,
                                         installed=", ".join(registry.packs) or "-"))


def _pairs(entries, option):
    pairs = {}
    for entry in entries:
        name, equals, value = entry.partition("=")
        if not equals or not name:
            raise BlockMakerError(app_local_text("pack_option_bad", option=option, value=entry))
        pairs[name.strip()] = value
    return pairs


def _value(text, kind):
    """A value typed on the command line, as the kind of value it is for."""
    if kind == "text" or too_deep(text):
        return text  # a value that nests too deeply for the parser is not one a field takes: said as not fitting
    return yaml.safe_load(text) if text.strip() else None


def _inputs(args, field_kinds) -> tuple:
    units, defaults, ranges = (_pairs(args.unit, "--unit"), _pairs(args.default, "--default"),
                               _pairs(args.range, "--range"))
    inputs = []
    for entry in args.input:
        head, _, kind = entry.partition(":")
        name, _, field = head.partition("=")
        kind = kind or field_kinds.get(field) or (field_kinds.get(args.read_field) if not field else None) or "number"
        low, _, high = ranges.get(name, ":").partition(":")
        inputs.append(BlockInput(name=name.strip(), kind=kind, field=field.strip(), unit=units.get(name, ""),
                                 default=_value(defaults[name], kind) if name in defaults else None,
                                 minimum=_value(low, "number") if low.strip() else None,
                                 maximum=_value(high, "number") if high.strip() else None))
    return tuple(inputs)


def made_block_from_args(args, profile) -> MadeBlock:
    """The MadeBlock ``rockly blocks make``'s options describe (kinds of inputs from ``profile``'s types)."""
    field_kinds = {entry.path: entry.kind for entry in fields_of_block_kind(profile, args.kind, args.type)}
    fixed = {path: _value(text, field_kinds.get(path, "number"))
             for path, text in _pairs(args.fixed, "--fixed").items()}
    fixed = {path: value for path, value in fixed.items() if value is not None}  # FIELD= keeps its default
    target = None
    if args.target is not None:
        target = _value(args.target, field_kinds.get(args.read_field, "number"))
    return MadeBlock(
        id=args.id, kind=args.kind, interface=args.interface, interface_type=args.type,
        inputs=_inputs(args, field_kinds), fixed=fixed,
        sentence={"en": args.sentence_en, "de": args.sentence_de},
        category={"en": args.category_en, "de": args.category_de}, colour=args.colour,
        tooltip={"en": args.tooltip_en, "de": args.tooltip_de}, read_field=args.read_field,
        value_kind=args.value_kind, comparison=args.comparison, target=target, result=args.result,
        while_waiting=args.while_waiting)


def _make(args, registry, language) -> int:
    if args.profile not in registry.profiles:
        raise BlockMakerError(app_local_text("pack_profile_missing", profile=args.profile,
                                             installed=", ".join(registry.profiles) or "-"))
    profile = registry.get(args.profile)
    _learn_type(args, profile)
    block = made_block_from_args(args, profile)
    pack = save_block(block, profile, args.pack, pack_name={"en": args.pack_name} if args.pack_name else None,
                      replace_block=args.replace)
    print(app_text("pack_made", language, id=block.id, pack=pack.id, path=pack.root))
    return 0


_LIVE_KINDS = {"publish": "topic", "sensor_value": "topic", "wait_until": "topic", "call_service": "service",
               "send_goal": "action"}


def _learn_type(args, profile) -> None:
    """Learn ``--type`` from the robot ``--backend`` names when ``profile`` has no definition for it (as the
    maker does); without a robot, a BlockMakerError saying to name one."""
    kind = INTERFACE_KINDS.get(args.kind)
    if not kind or not args.type or "/" not in args.type or knows_type(profile, args.type, kind):
        return
    if args.backend in (None, links.DEFAULT_KIND):  # the built-in simulator knows only what the profile knows
        raise BlockMakerError(app_local_text("pack_type_learn_robot", type=args.type))
    # read-only: a link's end is the safe stop, which would stop a program another client runs on the robot
    learnt = links.read_definition(args.backend, profile, connection(args.backend, args), _LIVE_KINDS[args.kind],
                                   args.interface, args.type)
    learn_definition(args.type, kind, learnt.text, learnt.nested)


def _list_packs(registry, language) -> int:
    """Every installed pack (id, version, the profile it adds to, its folder), then the broken ones; 1 if any is."""
    for pack in registry.packs.values():
        print(f"{pack.id:<24} {pack.version:<10} {pack.adds_to:<14} {pack.root}")
    for error in registry.pack_errors:
        print(f"BROKEN  {error.in_language(language)}", file=sys.stderr)
    return 1 if registry.pack_errors else 0


def _list(pack, language) -> int:
    print(f"{pack.id} {pack.version} (adds to {pack.adds_to}): {pack.display_name(language)}")
    for spec in pack.blocks:
        made = pack.made_block(spec.type)
        what = f"{made.kind} {made.interface} {made.interface_type}".rstrip() if made else "-"
        sentence = spec.definition.get("message0")
        if isinstance(sentence, dict):
            sentence = sentence.get(language) or sentence.get("en")
        print(f"  {spec.type:<24} {what:<50} {sentence}")
    return 0

