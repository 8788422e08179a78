"""Robot parts that only have the methods: wrapped in the base classes the loop takes."""
from . import _echoplan


class _ForwardingRobot(_echoplan.Robot):
    def __init__(self, robot):
        super().__init__()
        self._robot = robot

    def begin_trial(self, context):
        begin = getattr(self._robot, "begin_trial", None)
        if begin is not None:
            begin(context)

    def execute(self, action):
        return self._robot.execute(action)


class _ForwardingRecorder(_echoplan.Recorder):
    def __init__(self, recorder):
        super().__init__()
        self._recorder = recorder

    def begin_trial(self, context):
        begin = getattr(self._recorder, "begin_trial", None)
        if begin is not None:
            begin(context)

    def start(self, action):
        self._recorder.start(action)

    def stop(self):
        return self._recorder.stop()


class _ForwardingService(_echoplan.ObservationService):
    def __init__(self, service):
        super().__init__()
        self._service = service

    def vocabulary(self):
        vocabulary = getattr(self._service, "vocabulary", None)
        return vocabulary() if vocabulary is not None else None

    def observe(self, clip, action):
        return self._service.observe(clip, action)


def _wrap(part, base, forwarding, methods):
    if part is None or isinstance(part, base):
        return part
    missing = [m for m in methods if not callable(getattr(part, m, None))]
    if missing:
        raise TypeError(f"{type(part).__name__} is not a {base.__name__}: it has no "
                        f"{', '.join(missing)} method (subclass echoplan.{base.__name__}, or give "
                        f"it {', '.join(methods)})")
    return forwarding(part)


def as_robot(robot):
    """`robot` as an echoplan.Robot: itself when it is one, else a wrapper calling its
    execute(action) and, when it has one, begin_trial(context)."""
    return _wrap(robot, _echoplan.Robot, _ForwardingRobot, ["execute"])


def as_recorder(recorder):
    """`recorder` as an echoplan.Recorder (start(action), stop(); begin_trial optional)."""
    return _wrap(recorder, _echoplan.Recorder, _ForwardingRecorder, ["start", "stop"])


def as_service(service):
    """`service` as an echoplan.ObservationService (observe(clip, action); vocabulary optional)."""
    return _wrap(service, _echoplan.ObservationService, _ForwardingService, ["observe"])


def Loop(problem, *, robot=None, recorder=None, service=None, **kwargs):  # noqa: N802
    """The closed loop of `echoplan run` (see echoplan._echoplan.Loop for every argument). Robot
    parts may be subclasses of echoplan.Robot, Recorder and ObservationService, or any objects
    with their methods."""
    return _echoplan.Loop(problem, robot=as_robot(robot), recorder=as_recorder(recorder),
                          service=as_service(service), **kwargs)


Loop.__doc__ += "\n\n" + _echoplan.Loop.__doc__ + "\n\n" + _echoplan.Loop.__init__.__doc__
