"""``rockly agent`` (the agent on the robot) and ``rockly robot ...`` (a client on the command line); on a robot
with only ``rockly-runtime``: ``rockly-agent`` and ``rockly-robot``."""
import argparse
import json
import os
import signal
import sys
import threading
from pathlib import Path

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.runtime.agent.client import VIAS, AgentClient, AgentError
from rockly_desktop.runtime.agent.protocol import ALIVE_SECONDS, DEFAULT_NAMESPACE, DEFAULT_PORT
from rockly_desktop.runtime.agent.source_match import REASONS
from rockly_desktop.runtime.robot_limits import default_path as default_limits_path


def default_library() -> Path:
    """Where the agent keeps its programs without ``--library``."""
    data = os.environ.get("XDG_DATA_HOME") or os.path.join(os.path.expanduser("~"), ".local", "share")
    return Path(data) / "rockly" / "agent-programs"


def agent_main(argv=None) -> int:
    """``rockly-agent`` (what ``rockly-runtime`` installs on a robot): ``rockly agent`` without the window's
    ``rockly``."""
    parser = argparse.ArgumentParser(prog="rockly-agent", description=app_text("agent_help", "en"))
    _agent_options(parser)
    _language_option(parser)
    args = parser.parse_args(argv)
    return agent_command(args, args.language or "en")


def robot_main(argv=None) -> int:
    """``rockly-robot`` (in ``rockly-runtime``): ``rockly robot`` for standalone ``.py`` programs only (exporting a
    ``.rockly`` file needs the window's Rockly)."""
    parser = argparse.ArgumentParser(prog="rockly-robot", description=app_text("robot_help", "en"))
    _robot_options(parser)
    _language_option(parser)
    args = parser.parse_args(argv)
    return robot_command(args, args.language or "en", _standalone_file)


def _language_option(parser):
    from rockly_desktop.core.app_texts import languages

    parser.add_argument("--language", choices=languages(), help=app_text("cli_language_help", "en"))


def _standalone_file(path: Path) -> tuple:
    from rockly_desktop.core.errors import RocklyError
    from rockly_desktop.core.program import read_text_file

    try:
        return read_text_file(path), None
    except RocklyError as error:
        raise AgentError("program", str(error)) from None


def add_agent_parser(commands, language_option):
    """``rockly agent``'s command line."""
    agent = commands.add_parser("agent", help=app_text("agent_help", "en"))
    _agent_options(agent)
    language_option(agent)


def _agent_options(agent):
    from rockly_desktop.robot import links
    from rockly_desktop.runtime.agent.library import DEFAULT_QUOTA_BYTES
    from rockly_desktop.runtime.options import add_connection_options

    agent.add_argument("--backend", default=links.DEFAULT_KIND, choices=[entry.kind for entry in links.link_kinds()],
                       help=app_text("agent_backend_help", "en"))
    add_connection_options(agent, links.link_kinds())
    agent.add_argument("--library", type=Path, help=app_text("agent_library_help", "en", folder=default_library()))
    agent.add_argument("--host", default="0.0.0.0", help=app_text("agent_host_help", "en"))
    agent.add_argument("--port", type=int, default=DEFAULT_PORT, help=app_text("agent_port_help", "en"))
    agent.add_argument("--speed", type=float, default=1.0, help=app_text("standalone_speed_help", "en"))
    agent.add_argument("--library-quota", type=int, metavar="MB", default=DEFAULT_QUOTA_BYTES // 2**20,
                       help=app_text("agent_quota_help", "en", megabytes=DEFAULT_QUOTA_BYTES // 2**20))
    agent.add_argument("--robot-limits", metavar="FILE", type=Path,
                       help=app_text("standalone_robot_limits_help", "en", default=default_limits_path()))
    actions = agent.add_subparsers(dest="agent_action", metavar="limits|pair|clients|revoke")
    pair = actions.add_parser("pair", help=app_text("agent_pair_help", "en"))
    pair.add_argument("--role", choices=("teacher", "student"), help=app_text("agent_pair_role_help", "en"))
    actions.add_parser("clients", help=app_text("agent_clients_help", "en"))
    revoke = actions.add_parser("revoke", help=app_text("agent_revoke_help", "en"))
    revoke.add_argument("name", metavar="NAME")
    limits = actions.add_parser("limits", help=app_text("agent_limits_help", "en"))
    limits.add_argument("--max-speed", type=float, metavar="M/S", help=app_text("agent_limits_speed_help", "en"))
    limits.add_argument("--max-turn", type=float, metavar="DEG/S", help=app_text("agent_limits_turn_help", "en"))
    limits.add_argument("--switch-off", action="append", default=[], metavar="CAPABILITY",
                        help=app_text("agent_limits_off_help", "en"))
    limits.add_argument("--none", action="store_true", help=app_text("agent_limits_none_help", "en"))
    agent.add_argument("--namespace", default=DEFAULT_NAMESPACE,
                       help=app_text("agent_namespace_help", "en", namespace=DEFAULT_NAMESPACE))
    agent.add_argument("--offer-on-robot-ui", metavar="PROFILE", help=app_text("agent_offer_help", "en"))
    agent.add_argument("--no-pairing-on-robot-ui", action="store_true",
                       help=app_text("agent_no_robot_ui_pairing_help", "en"))
    agent.add_argument("--no-source-check", action="store_true", help=app_text("agent_no_source_check_help", "en"))


def add_robot_parser(commands, language_option):
    """``rockly robot list|send|start|stop|delete|attach``'s command line."""
    robot = commands.add_parser("robot", help=app_text("robot_help", "en"))
    _robot_options(robot)
    language_option(robot)


def _robot_options(robot):
    robot.add_argument("--host", default="localhost", help=app_text("robot_host_help", "en"))
    robot.add_argument("--port", type=int, default=DEFAULT_PORT, help=app_text("agent_port_help", "en"))
    robot.add_argument("--via", choices=VIAS, default="auto", help=app_text("robot_via_help", "en"))
    robot.add_argument("--master", help=app_text("robot_master_help", "en"))
    robot.add_argument("--domain", type=int, help=app_text("robot_domain_help", "en"))
    robot.add_argument("--namespace", default=DEFAULT_NAMESPACE,
                       help=app_text("agent_namespace_help", "en", namespace=DEFAULT_NAMESPACE))
    actions = robot.add_subparsers(dest="robot_command", required=True)
    pair = actions.add_parser("pair", help=app_text("robot_pair_help", "en"))
    pair.add_argument("code")
    pair.add_argument("--name", help=app_text("robot_pair_name_help", "en"))
    actions.add_parser("list", help=app_text("robot_list_help", "en"))
    send = actions.add_parser("send", help=app_text("robot_send_help", "en"))
    send.add_argument("program", type=Path)
    send.add_argument("--name", help=app_text("robot_name_help", "en"))
    send.add_argument("--keep-going", action="store_true", help=app_text("robot_keep_going_help", "en"))
    send.add_argument("--decide-seconds", type=float, default=2.0, help=app_text("robot_decide_help", "en"))
    start = actions.add_parser("start", help=app_text("robot_start_help", "en"))
    start.add_argument("name")
    start.add_argument("--answer", action="append", default=[], help=app_text("standalone_answer_help", "en"))
    actions.add_parser("stop", help=app_text("robot_stop_help", "en"))
    delete = actions.add_parser("delete", help=app_text("robot_delete_help", "en"))
    delete.add_argument("name")
    attach = actions.add_parser("attach", help=app_text("robot_attach_help", "en"))
    attach.add_argument("--watch-only", action="store_true", help=app_text("robot_watch_only_help", "en"))


def agent_command(args, language: str) -> int:
    """``rockly agent``: serve, or ``rockly agent limits``: show or set the robot's own limits."""
    action = getattr(args, "agent_action", None)
    if action == "limits":
        return limits_command(args, language)
    if action in ("pair", "clients", "revoke"):
        return pairing_command(args, language)
    return serve(args, language)


def pairing_command(args, language: str) -> int:
    """``rockly agent pair``: a one-time code (and the certificate's fingerprint to compare); ``clients``: the
    paired laptops; ``revoke NAME``: forget one. They work on the agent's folder, also while the agent runs
    (docs/decisions/035)."""
    from rockly_desktop.runtime.agent.pairings import Pairings, agent_folder
    from rockly_desktop.runtime.agent.tls import folder_fingerprint, short_fingerprint

    folder = agent_folder(args.library or default_library())
    pairings = Pairings(folder)
    owner = _other_owner(folder)
    if owner is not None:  # what this command wrote, the agent's own user could not read
        print(app_text("agent_pair_other_user", language, folder=folder, owner=owner), file=sys.stderr)
        return 1
    try:
        if args.agent_action == "pair":
            code = pairings.new_code(args.role)
            print(app_text("agent_pair_code", language, code=code.shown, role=app_text("role_" + code.role, language),
                           minutes=2, fingerprint=short_fingerprint(folder_fingerprint(folder))))
            return 0
        if args.agent_action == "clients":
            for client in pairings.clients():
                print(app_text("agent_client_line", language, name=client.name, id=client.id,
                               role=app_text("role_" + client.role, language), paired=client.paired_at))
            if not pairings.clients():
                print(app_text("agent_no_clients", language))
            return 0
        if not pairings.revoke(args.name):
            print(app_text("agent_revoke_none", language, name=args.name), file=sys.stderr)
            return 1
        print(app_text("agent_revoked", language, name=args.name))
        return 0
    except OSError as error:
        print(app_text("agent_pairings_unusable", language, folder=folder, reason=error.strerror or str(error)),
              file=sys.stderr)
        return 1


def _other_owner(folder: Path):
    """The name of the user owning the agent's ``folder`` (or its library) when that is not this process's user
    (root running ``rockly agent pair`` for a service's agent); None when it is, or there is no folder yet."""
    for path in (folder, folder.parent):
        try:
            owner = path.stat().st_uid
        except OSError:
            continue
        if owner == os.geteuid():
            return None
        import pwd

        try:
            return pwd.getpwuid(owner).pw_name
        except KeyError:
            return str(owner)
    return None


def limits_command(args, language: str) -> int:
    """Show the robot's limits, or change those given (``--none``: none); a speed below 0 is refused."""
    from rockly_desktop.robot.wrappers.limits import Limits
    from rockly_desktop.runtime.robot_limits import RobotLimitsError, read_robot_limits, write_robot_limits

    path = args.robot_limits
    try:
        limits = Limits() if args.none else read_robot_limits(path)
    except RobotLimitsError as error:
        print(error.in_language(language), file=sys.stderr)
        return 1
    speeds = {"max_speed": args.max_speed, "max_turn": args.max_turn}
    if any(value is not None and not value >= 0 for value in speeds.values()):
        print(app_text("agent_limits_negative", language), file=sys.stderr)
        return 2
    if args.none or args.switch_off or any(value is not None for value in speeds.values()):
        limits = Limits(speeds["max_speed"] if args.max_speed is not None else limits.max_speed,
                        speeds["max_turn"] if args.max_turn is not None else limits.max_turn,
                        frozenset(limits.switched_off | set(args.switch_off)))
        try:
            path = write_robot_limits(limits, path)
        except OSError as error:
            print(app_text("agent_limits_cannot_write", language, reason=error.strerror or str(error)),
                  file=sys.stderr)
            return 1
    print(app_text("agent_limits_now", language, path=path or default_limits_path(),
                   speed="-" if limits.max_speed is None else limits.max_speed,
                   turn="-" if limits.max_turn is None else limits.max_turn,
                   off=", ".join(sorted(limits.switched_off)) or "-"))
    return 0


def serve(args, language: str) -> int:
    """Run the agent until SIGTERM or Ctrl+C; a running program is stopped first (its safe stop runs)."""
    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.robot import links
    from rockly_desktop.runtime.agent.library import Library
    from rockly_desktop.runtime.agent.pairings import Pairings, agent_folder
    from rockly_desktop.runtime.agent.server import Agent
    from rockly_desktop.runtime.agent.source_match import SourceChecks
    from rockly_desktop.runtime.agent.tcp_transport import AgentServer
    from rockly_desktop.runtime.agent.tls import server_context
    from rockly_desktop.runtime.options import connection

    folder = args.library or default_library()
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        print(app_text("agent_no_library", language, folder=folder, reason=error.strerror), file=sys.stderr)
        return 1
    options = ["--speed", str(args.speed), "--language", language, "--robot-limits",
               str(args.robot_limits or default_limits_path())]
    for setting in links.link_kind(args.backend).settings:
        value = connection(args.backend, args).get(setting.name)
        if setting.option and value is not None:
            options += [setting.option, str(value)]
    try:
        context = server_context(agent_folder(folder))
    except OSError as error:
        print(app_text("agent_pairings_unusable", language, folder=agent_folder(folder),
                       reason=error.strerror or str(error)), file=sys.stderr)
        return 1
    agent = Agent(Library(folder, ProfileRegistry.discover().profiles, args.library_quota * 2**20), args.backend,
                  options, Pairings(agent_folder(folder)))
    agent.robot_limits_path = args.robot_limits or default_limits_path()  # a paired teacher may set them
    agent.source_checks = SourceChecks(agent.library, agent.changed, enabled=not args.no_source_check)
    close_offer = _offer_on_robot_ui(agent, args, language)
    if close_offer is False:
        return 2
    try:
        server = AgentServer(agent, args.host, args.port, context)
    except OSError as error:
        print(app_text("agent_cannot_listen", language, host=args.host, port=args.port, reason=error.strerror),
              file=sys.stderr)
        if close_offer:
            close_offer()
        return 1
    ending = threading.Event()
    for signum in (signal.SIGTERM, signal.SIGINT):
        signal.signal(signum, lambda *_: ending.set())
    threading.Thread(target=server.serve_forever, daemon=True, name="agent-server").start()
    print(app_text("agent_ready", language, host=args.host, port=server.server_address[1], folder=folder,
                   backend=args.backend), flush=True)
    ros_calls = _offer_on_ros(agent, args, language) if links.link_kind(args.backend).agent_topics else None
    if close_offer:
        print(app_text("agent_menu_offered", language, profile=args.offer_on_robot_ui), flush=True)
    # its own thread: a send to a client behind a cut network may block, and must not keep SIGTERM from ending
    threading.Thread(target=_say_alive, args=(agent, ending), daemon=True, name="agent-alive").start()
    while not ending.wait(0.5):
        pass
    if close_offer:
        close_offer()
    server.shutdown()
    if ros_calls is not None:
        ros_calls.close()
    agent.shut_down()
    server.server_close()
    return 0


def _say_alive(agent, ending):
    while not ending.wait(ALIVE_SECONDS):
        agent.say_alive()
        agent.check_pairings()  # a client revoked meanwhile (``rockly agent revoke``) is cut off


def _offer_on_ros(agent, args, language: str):
    """The agent's calls on the robot's ROS graph too (``agent.ros_transport``: ROS 1's master, ROS 2's domain);
    None (said on standard error) when it cannot be reached: TCP still serves."""
    from rockly_desktop.runtime.agent.ros_transport import RosOffer
    from rockly_desktop.runtime.options import connection

    where = args.master if args.backend == "ros1" else connection(args.backend, args)
    try:
        offer = RosOffer(agent, args.backend, args.namespace, where, language)
    except AgentError as error:
        print(f"rockly agent: {error.message}", file=sys.stderr, flush=True)
        return None
    print(offer.ready, flush=True)
    return offer


def _offer_on_robot_ui(agent, args, language):
    """With ``--offer-on-robot-ui``: its ``close()``, or False when it cannot be offered (said why); else None."""
    if not args.offer_on_robot_ui:
        return None
    from rockly_desktop.runtime.agent.robot_menu import NotOffered, offer_on_robot_ui
    from rockly_desktop.runtime.options import connection

    try:
        return offer_on_robot_ui(agent, agent.library.profiles, args.offer_on_robot_ui, args.backend,
                                 connection(args.backend, args), language, pairing=not args.no_pairing_on_robot_ui)
    except NotOffered as reason:
        print(f"rockly agent: {reason}", file=sys.stderr, flush=True)
        return False


def robot_command(args, language: str, standalone_of=None) -> int:
    """Run one ``rockly robot`` action; ``standalone_of(path)``: ``(standalone text, .rockly text or None)`` of
    a program file (exporting it when it is a ``.rockly`` file: the caller's, which has the blocks)."""
    done = threading.Event()

    def show(event):
        print(json.dumps(event, ensure_ascii=False), flush=True)
        if event.get("event") == "run" and event.get("state") == "ended":
            done.set()

    try:
        client = AgentClient(args.host, args.port, language,
                             on_event=show if args.robot_command == "attach" else None,
                             on_closed=done.set, name="rockly robot", via=args.via,
                             master=args.master, namespace=args.namespace, domain=args.domain)
    except AgentError as error:
        print(f"rockly robot: {error.message}", file=sys.stderr)
        return 1
    try:
        return _act(client, args, language, standalone_of, done)
    except AgentError as error:
        print(f"rockly robot: {error.message}", file=sys.stderr)
        return 1
    finally:
        client.close()


def code_state_text(about: dict, language: str) -> str:
    """What a kept program's ``about.json`` says of its code against its blocks (``agent.source_match``), in
    ``language``."""
    state = about.get("code", "unchecked")  # kept by an agent older than the check
    if state not in ("same", "differs", "unchecked", "no_source", "checking"):
        state = "unchecked"
    reason = str(about.get("code_reason", "-"))
    if reason in REASONS:
        reason = app_text("robot_code_reason_" + reason, language)
    part = about.get("code_part", "code")
    part = app_text("robot_code_part_" + part, language) if part in ("code", "blocks", "variables") else "-"
    return app_text("robot_code_" + state, language, part=part, reason=reason)


def _act(client, args, language, standalone_of, done) -> int:
    action = args.robot_command
    if action == "pair":
        return _pair(client, args, language)
    if action == "list":
        answer = client.programs()
        for about in answer["programs"]:
            print(app_text("robot_program_line", language, name=about["name"], profile=about["profile"],
                           version=about["profile_version"], received=about["received"],
                           lost=app_text("robot_lost_" + about["on_lost_editor"], language,
                                         seconds=about["decide_seconds"])))
            print("  " + code_state_text(about, language))
        if not answer["programs"]:
            print(app_text("robot_no_programs", language))
        if answer["run"]:
            print(app_text("robot_running", language, name=answer["run"]["program"], state=answer["run"]["state"]))
        return 0
    if action == "send":
        standalone, source = standalone_of(args.program)
        name = args.name or args.program.stem
        about = client.send(name, standalone, source, "keep_going" if args.keep_going else "stop", args.decide_seconds)
        print(app_text("robot_sent", language, name=name))
        replaced = about.get("replaced")
        if replaced:
            print(app_text("robot_replaced", language, name=name, sender=replaced.get("sender", "?"),
                           received=replaced.get("received", "?")))
        return 0
    if action == "start":
        client.start(args.name, args.answer)
        print(app_text("robot_started", language, name=args.name))
        return 0
    if action == "stop":
        print(app_text("robot_stopped" if client.stop() else "robot_nothing_running", language))
        return 0
    if action == "delete":
        client.delete(args.name)
        print(app_text("robot_deleted", language, name=args.name))
        return 0
    answer = client.attach(control=not args.watch_only)
    print(json.dumps({"event": "attached", **answer}, ensure_ascii=False), flush=True)
    if answer["controlled_elsewhere"]:
        print(app_text("robot_watch_only", language), file=sys.stderr)
    if answer["run"] is None or answer["run"]["state"] == "ended":
        return 0
    try:
        done.wait()
    except KeyboardInterrupt:
        return 130
    return 0


def _pair(client, args, language) -> int:
    """``rockly robot pair CODE``: over TCP (TLS), where with ``--master`` or ``--domain`` the key serves that ROS
    graph's agent too; or over ROS (the code and the key sealed, ``agent.ros_transport``)."""
    from rockly_desktop.runtime.agent.robot_keys import ros_address
    from rockly_desktop.runtime.agent.tls import short_fingerprint

    also = []
    if client.via == "tcp" and args.domain is not None:
        also.append(ros_address("ros2", args.domain, args.namespace))
    elif client.via == "tcp" and args.master:
        also.append(ros_address("ros1", args.master, args.namespace))
    key = client.pair(args.code, args.name, also)
    if client.via == "ros":
        print(app_text("robot_paired_ros", language, agent=key.agent, role=app_text("role_" + key.role, language),
                       path=client.keys.path))
        return 0
    print(app_text("robot_paired", language, agent=key.agent, role=app_text("role_" + key.role, language),
                   fingerprint=short_fingerprint(key.fingerprint), path=client.keys.path))
    return 0
