"""Problems from Python dicts, and the shipped files."""
import os

from . import _echoplan


def shipped_file(relative):
    """The path of a file shipped with echoplan, e.g. shipped_file('problems/audio_objects.yaml')."""
    root = os.environ.get("ECHOPLAN_DATA_DIR")
    if not root:
        raise FileNotFoundError("echoplan's shipped data was not found; set ECHOPLAN_DATA_DIR")
    path = os.path.join(root, relative)
    if not os.path.isfile(path):
        raise FileNotFoundError(path)
    return path


def problem_from_dict(problem, name="<dict>"):
    """A problem from a dict with the keys of a YAML problem file (docs/problems.md), e.g.
    yaml.safe_load(open('problems/audio_objects.yaml')) edited in Python. The dict is written as
    YAML and read by the same reader as a file, with the same checks; an InputError then names
    `name`, the line of that YAML and, in its message, the line's text."""
    import yaml  # Debian's python3-yaml; imported here so `import echoplan` does not need it

    text = yaml.safe_dump(problem, sort_keys=False, default_flow_style=None)
    try:
        return _echoplan.parse_problem(text, name + ".yaml")
    except _echoplan.InputError as error:
        lines = text.splitlines()
        if 1 <= error.line <= len(lines):
            error.args = (f"{error.args[0]} (the dict as YAML, line {error.line}: "
                          f"{lines[error.line - 1].strip()!r})",)
        raise
