"""The command-line options of the robot links' connection settings (``--master-uri``, ``--domain-id``, ...),
for ``rockly run``/``rockly sim`` and a standalone export alike; the kinds come from ``robot.links``."""


def add_connection_options(parser, kinds):
    """Add the command-line options of ``kinds``' connection settings to ``parser`` (each option once)."""
    added = set()
    for entry in kinds:
        for setting in entry.settings:
            if setting.option and setting.option not in added:
                added.add(setting.option)
                parser.add_argument(setting.option, dest=_option_dest(setting), help=setting.help)


def connection(kind: str, args) -> dict:
    """The connection settings of ``kind`` given on the command line (``args`` from the parser)."""
    from rockly_desktop.robot import links

    return {setting.name: getattr(args, _option_dest(setting)) for setting in links.link_kind(kind).settings
            if setting.option}


def _option_dest(setting) -> str:
    return setting.option.lstrip("-").replace("-", "_")
