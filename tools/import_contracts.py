"""Import contracts of Rockly's own, for rules import-linter's built-in types cannot say
(``pyproject.toml`` names them under ``contract_types``; ``lint-imports`` finds this module
from the repository's folder)."""
import ast
import importlib.util

from importlinter.application import output
from importlinter.domain import fields
from importlinter.domain.contract import Contract, ContractCheck


class OnlySomeModulesContract(Contract):
    """The ``source_modules`` (with their sub-modules) import only the ``allowed_modules`` of the
    outside ``package``: e.g. only ``PySide6.QtCore`` of PySide6.

    import-linter sees an outside package only as a whole (``PySide6``, never ``PySide6.QtWidgets``),
    so the source of each module that imports it is read for the package's modules it names.
    """

    type_name = "only_some_modules"

    source_modules = fields.ListField(subfield=fields.ModuleField())
    package = fields.StringField()
    allowed_modules = fields.ListField(subfield=fields.StringField())

    def check(self, graph, verbose: bool) -> ContractCheck:
        wrong = []
        for source in self.source_modules:
            for module in sorted({source.name} | graph.find_descendants(source.name)):
                if self.package in graph.find_modules_directly_imported_by(module):
                    wrong += [(module, name, line) for name, line in modules_named(module, self.package)
                              if name not in self.allowed_modules]
        return ContractCheck(kept=not wrong, metadata={"wrong": wrong})

    def render_broken_contract(self, check: ContractCheck) -> None:
        output.print_error(f"Only {', '.join(self.allowed_modules)} of {self.package} may be imported:", bold=False)
        output.new_line()
        for module, name, line in check.metadata["wrong"]:
            output.print_error(f"- {module} -> {name} (l.{line})", bold=False)
        output.new_line()


def modules_named(module: str, package: str) -> list:
    """[(``package``'s module, line)] for each import of ``package`` in ``module``'s source: its
    first-level module (``PySide6.QtCore`` for ``from PySide6.QtCore.Qt import …`` or ``from PySide6
    import QtCore``), or the package itself for a bare ``import PySide6``."""
    origin = importlib.util.find_spec(module).origin
    with open(origin, encoding="utf-8") as file:
        tree = ast.parse(file.read(), origin)
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names = ([f"{package}.{alias.name}" for alias in node.names] if node.module == package
                     else [node.module])
        else:
            continue
        found += [(".".join(name.split(".")[:2]), node.lineno) for name in names
                  if name.split(".")[0] == package]
    return found
