"""The click command tree of a typer app, each subcommand built when it is first looked up.

typer turns every command of the tree into a click command (reading each function's signature
and annotations) before it parses the command line: for ttctl's forty-odd commands that was
about 25 ms on every start, a fifth of `ttctl validate`'s whole run. Here only the group being
walked and the command being run are built; `--help` of a group builds what it lists. The
commands themselves are typer's own (`get_command_from_info`), so options, help and errors are
exactly typer's.
"""

from __future__ import annotations

import copy
import functools
from collections.abc import Callable, Iterator
from typing import Any

import click
from typer.core import TyperArgument
from typer.main import (
    get_command_from_info,
    get_command_name,
    get_group_from_info,
    solve_typer_info_defaults,
)
from typer.models import TyperInfo


def _keep_argument_help() -> None:
    """click 8.5's Argument takes a `help` of its own and sets it (None) after typer's
    TyperArgument has stored the declared one, so every argument's help vanished from `--help`.
    Put the declared text back once the base class is done."""
    init = TyperArgument.__init__
    if getattr(init, "__ttctl_keeps_help__", False):
        return

    @functools.wraps(init)
    def keep(self: TyperArgument, *args: Any, help: str | None = None, **kw: Any) -> None:
        init(self, *args, help=help, **kw)
        if help is not None and getattr(self, "help", None) is None:
            self.help = help

    keep.__ttctl_keeps_help__ = True  # type: ignore[attr-defined]
    TyperArgument.__init__ = keep  # type: ignore[method-assign]


_keep_argument_help()


class LazyCommands(dict[str, Any]):
    """name -> click command; each value is built by its builder on first access. Keys (and
    their order: typer lists commands as defined) are known from the start."""

    def __init__(self, builders: dict[str, Callable[[], click.Command]]) -> None:
        super().__init__((name, None) for name in builders)
        self._builders = builders

    def __getitem__(self, name: str) -> click.Command:
        cmd: click.Command | None = super().__getitem__(name)
        if cmd is None:
            cmd = self._builders[name]()
            super().__setitem__(name, cmd)
        return cmd

    def get(self, name: str, default: Any = None) -> Any:
        return self[name] if name in self else default  # noqa: SIM401 (self.get is this method)

    def values(self) -> Any:  # a dict view of the built commands
        return {k: self[k] for k in self}.values()

    def items(self) -> Any:
        return {k: self[k] for k in self}.items()

    def __iter__(self) -> Iterator[str]:
        return iter(list(super().keys()))


def _command(ci: Any, opts: dict[str, Any]) -> click.Command:
    """typer's command for `ci`, its float options refusing NaN and infinity (`finite`)."""
    from .finite import finite_floats

    return finite_floats(get_command_from_info(ci, **opts))


def lazy_group(info: TyperInfo, *, pretty_exceptions_short: bool, rich_markup_mode: Any,
               suggest_commands: bool) -> click.Group:
    """typer's group for `info`, its callback and options built now, its commands (and
    subgroups, recursively) when first asked for."""
    opts = {"pretty_exceptions_short": pretty_exceptions_short, "rich_markup_mode": rich_markup_mode}
    instance = info.typer_instance
    assert instance is not None
    shell = copy.copy(instance)
    shell.registered_commands = []
    shell.registered_groups = []
    shell_info = copy.copy(info)
    shell_info.typer_instance = shell
    group = get_group_from_info(shell_info, suggest_commands=suggest_commands, **opts)
    builders: dict[str, Callable[[], click.Command]] = {}
    for ci in instance.registered_commands:
        assert ci.callback is not None
        name = ci.name or get_command_name(ci.callback.__name__)
        builders[name] = functools.partial(_command, ci, opts)
    for gi in instance.registered_groups:
        group_name = solve_typer_info_defaults(gi).name
        assert isinstance(group_name, str) and group_name, "every subgroup of ttctl is added with a name"
        builders[group_name] = functools.partial(lazy_group, gi, suggest_commands=suggest_commands, **opts)
    group.commands = LazyCommands(builders)
    return group


def lazy_command(app: Any) -> click.Group:
    """The root group of a typer app whose commands are built on demand."""
    return lazy_group(TyperInfo(app), pretty_exceptions_short=app.pretty_exceptions_short,
                      rich_markup_mode=app.rich_markup_mode, suggest_commands=app.suggest_commands)


__all__ = ["LazyCommands", "lazy_command", "lazy_group"]
