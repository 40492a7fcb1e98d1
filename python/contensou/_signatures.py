"""``inspect.signature`` for the extension's classes.

nanobind's functions carry their signature as text (``__nb_signature__``), which ``inspect``
does not read, so ``inspect.signature(ContactPatch)`` would fail (and with it IDEs' and
notebooks' call hints). ``attach`` parses that text once at import and sets each class's
``__signature__`` (the constructor's parameters without ``self``, defaults as nanobind holds
them). A class whose constructor is overloaded keeps none (no one signature is right).
"""

from __future__ import annotations

import ast
import inspect
import re
from typing import Any, Optional

_KINDS = (("posonlyargs", inspect.Parameter.POSITIONAL_ONLY),
          ("args", inspect.Parameter.POSITIONAL_OR_KEYWORD),
          ("kwonlyargs", inspect.Parameter.KEYWORD_ONLY))


def _parameters(text: str, defaults: tuple) -> Optional[list[inspect.Parameter]]:
    """The parameters of one nanobind signature text ('def __init__(self, a: float = \\0) ->
    None'), with the placeholders \\k replaced by defaults[k]."""
    source = re.sub(r"\\(\d+)", r"__nb_default_\1", text.strip())
    try:
        tree = ast.parse(source + ": ...")
    except SyntaxError:
        return None
    fn = tree.body[0]
    if not isinstance(fn, ast.FunctionDef):
        return None
    params: list[inspect.Parameter] = []
    args = fn.args
    positional = args.posonlyargs + args.args
    pos_defaults: list[Optional[ast.expr]] = [None] * (len(positional) - len(args.defaults))
    pos_defaults += args.defaults
    kw_defaults: list[Optional[ast.expr]] = list(args.kw_defaults)
    for field, kind in _KINDS:
        for a in getattr(args, field):
            if a.arg == "self":
                continue
            node = (pos_defaults[positional.index(a)] if field != "kwonlyargs"
                    else kw_defaults[args.kwonlyargs.index(a)])
            default: Any = inspect.Parameter.empty
            if node is not None:
                name = ast.unparse(node)
                m = re.fullmatch(r"__nb_default_(\d+)", name)
                if m and int(m.group(1)) < len(defaults):
                    default = defaults[int(m.group(1))]
                else:  # a literal of a custom signature (nb::sig): its value
                    try:
                        default = ast.literal_eval(node)
                    except ValueError:
                        default = name
            annotation = ast.unparse(a.annotation) if a.annotation is not None else inspect.Parameter.empty
            params.append(inspect.Parameter(a.arg, kind, default=default, annotation=annotation))
    return params


def attach(module: Any) -> None:
    """Sets ``__signature__`` on every public class of ``module`` whose ``__init__`` is a
    nanobind function with one signature."""
    for name in dir(module):
        cls = getattr(module, name)
        # Private bases (_ExactLaw) are skipped: their Python subclasses (ExactLaw) would
        # inherit the attribute and show the base's signature instead of their own.
        if not isinstance(cls, type) or name.startswith("_"):
            continue
        overloads = getattr(cls.__dict__.get("__init__"), "__nb_signature__", None)
        if not overloads or len(overloads) != 1:
            continue
        text, _doc, defaults = overloads[0]
        params = _parameters(text, tuple(defaults or ()))
        if params is None:
            continue
        try:
            setattr(cls, "__signature__", inspect.Signature(params))
        except (TypeError, ValueError, AttributeError):
            continue
