"""The agent's programs offered on the robot's own UI (``rockly agent --offer-on-robot-ui PROFILE``).

The profile's ``program_menu`` hook (an SDK ``ProgramMenu``) asks the person; this offers it the programs kept
for that profile, again after each answer, when the library changes and when a run starts or ends, and does
what the person chose through the agent, as a client's request would (a start while one runs is refused).

Where the profile's menu offers pairing (its manifest's ``pairing``) and the agent allows it, a person at the robot
may ask it for a one-time pairing code (``Pairings.new_code``, as ``rockly agent pair`` on the robot's console): the
code is shown on the robot's UI only; the agent's log says that one was shown, never the code. Nobody on the network
can ask for one this way: only the person answering the robot's own question.
"""
import sys
import threading

from rockly_desktop.core.app_texts import app_catalogue, app_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.program_menu import MenuChoice
from rockly_desktop.runtime.agent.pairings import CODE_SECONDS
from rockly_desktop.runtime.agent.protocol import AgentRefusal, refusal_text
from rockly_desktop.runtime.agent.server import ON_THE_ROBOT

RETRY_SECONDS = 5.0  # after the robot's UI could not be reached


class NotOffered(Exception):
    """The programs cannot be offered on this robot's UI; the message says why, in the agent's language."""


def offer_on_robot_ui(agent, profiles: dict, profile_id: str, kind: str, connection: dict, language: str,
                      pairing: bool = True):
    """Start offering ``agent``'s programs for ``profile_id`` (one of ``profiles``) on the robot's own UI, through a
    link of ``kind`` with its ``connection`` settings; with ``pairing``, pairing codes too where the profile's menu
    can show them. Returns ``close()``: the offer ends and the link is shut.
    Raises NotOffered: no such profile, the built-in simulator (nobody sees its UI), a profile that declares no
    ``program_menu``, a robot that cannot be reached."""
    from rockly_desktop.robot import links

    profile = profiles.get(profile_id)
    if profile is None:
        raise NotOffered(app_text("agent_menu_no_profile", language, profile=profile_id,
                                  installed=", ".join(sorted(profiles))))
    if links.link_kind(kind).simulated:
        raise NotOffered(app_text("agent_menu_needs_robot", language, profile=profile_id))
    try:
        menu = profile.program_menu(language)
        if menu is None:
            raise NotOffered(app_text("agent_menu_not_offered", language, robot=profile.display_name(language)))
        menu.offers_pairing = menu.offers_pairing and pairing
        link = links.open_link(kind, profile, connection)
    except RocklyError as error:
        raise NotOffered(app_text("agent_menu_cannot_start", language, reason=_said(error, language))) from None
    offer = RobotMenu(agent, menu, profile.id, link.backend)

    def close():
        offer.close()
        link.shutdown()
    return close


def _said(error: RocklyError, language: str) -> str:
    """``error`` in ``language``: a robot that cannot be reached by its ``reason``'s text (``ros_REASON``)."""
    key = f"ros_{getattr(error, 'reason', None)}"
    if key in app_catalogue():
        return app_text(key, language, **getattr(error, "values", {}))
    return error.in_language(language)


class RobotMenu:
    """Offers ``agent``'s programs of ``profile_id`` through ``menu`` on a thread of its own until ``close()``.

    ``backend_for(interrupt)``: a RobotBackend whose waits end when ``interrupt`` is stopped (a robot link's
    ``backend``): each question gets its own, stopped when what is offered changes, so the new offer comes at once.
    ``say(text)`` tells the robot's log what went wrong (each problem once until it changes)."""

    def __init__(self, agent, menu, profile_id: str, backend_for,
                 say=lambda text: print(text, file=sys.stderr, flush=True)):
        self.agent = agent
        self.menu = menu
        self.profile_id = profile_id
        self._backend_for = backend_for
        self._say = say
        self._said = None
        self._lock = threading.Lock()
        self._asking = None  # the Interrupt of the question open now
        self._changed = threading.Event()
        self._changed.set()  # the first offer
        self._closing = threading.Event()
        agent.listeners.append(self.changed)
        self._thread = threading.Thread(target=self._offer, daemon=True, name="agent-robot-menu")
        self._thread.start()

    def changed(self):
        """What is offered has changed (the library, the run): an open question is abandoned and asked anew."""
        with self._lock:
            self._changed.set()
            if self._asking is not None:
                self._asking.request_stop()

    def close(self, timeout: float = 10.0):
        """Offer nothing more; an open question is abandoned."""
        self._closing.set()
        self.agent.listeners.remove(self.changed)
        self.changed()
        self._thread.join(timeout)

    def _offer(self):
        while True:
            self._changed.wait()
            if self._closing.is_set():
                return
            self._changed.clear()
            programs, running = self._offer_now()
            if running is None and not programs and not self.menu.offers_pairing \
                    or running is not None and not self.menu.offers_stop:
                continue  # offered again when the library changes or the run ends
            choice = self._ask(self.menu.choose, programs, running)
            if choice is not None and choice.action == MenuChoice.PAIR:
                self._show_code()
                self._changed.set()  # then the programs again
            elif choice is None or not self._act(choice, running):
                self._changed.set()  # asked again at once (a start or a stop done is a change of its own)

    def _show_code(self):
        """A new one-time pairing code (its role: ``Pairings.new_code``'s default), shown on the robot's UI; the
        agent's log says one was shown, not the code."""
        def show(backend):
            try:
                code = self.agent.pairings.new_code()
            except OSError as error:  # the agent's folder cannot be written
                self._problem(app_text("agent_menu_no_code", self.menu.language, reason=error.strerror or str(error)))
                return
            self._say("rockly agent: " + app_text("agent_menu_code_shown", self.menu.language,
                                                  role=app_text("role_" + code.role, self.menu.language),
                                                  minutes=int(CODE_SECONDS) // 60))
            self.menu.show_pairing_code(backend, code.shown, int(CODE_SECONDS))
        self._ask(show)

    def _ask(self, question, *args):
        """``question(backend, *args)``'s answer (the person's choice), or None (also when the question was abandoned or
        failed; then asked anew)."""
        asking = Interrupt()
        with self._lock:
            if self._changed.is_set():  # changed meanwhile: offer the new state
                return None
            self._asking = asking
        try:
            choice = question(self._backend_for(asking), *args)
        except RocklyError as error:
            if asking.stop_requested:
                return None
            self._problem(error.in_language(self.menu.language))
            self._closing.wait(RETRY_SECONDS)
            return None
        finally:
            with self._lock:
                self._asking = None
        self._said = None
        return None if asking.stop_requested else choice

    def _offer_now(self) -> tuple:
        """``(names of the programs for this robot, the running program's name or None)``."""
        programs = [about["name"] for about in self.agent.library.entries() if about.get("profile") == self.profile_id]
        run = self.agent.run
        return sorted(programs, key=str.casefold), (run.about["name"] if run is not None else None)

    def _act(self, choice: MenuChoice, running) -> bool:
        """Do ``choice``; True when it started or stopped a run (whose start or end is offered anew)."""
        try:
            if choice.action == MenuChoice.START:
                self.agent.handle(ON_THE_ROBOT, {"op": "start", "name": choice.name})
                return True
            run = self.agent.run
            if choice.action == MenuChoice.STOP and run is not None and run.about["name"] == running:
                return self.agent.handle(ON_THE_ROBOT, {"op": "stop"})["stopped"]  # not another started since
        except AgentRefusal as refusal:
            self._problem(refusal_text(refusal, self.menu.language))
        return False

    def _problem(self, text: str):
        if text != self._said:
            self._said = text
            self._say(f"rockly agent: {text}")
