# The type stubs (python/asperity/*.pyi, written by hand) checked against the module they
# describe, so that they cannot drift from it: every public name of the module (function, class,
# method, property, enum member, record field) is in the stubs and every name in the stubs is in
# the module; a function's or method's parameters (names, order, which are keyword-only, which
# have a default) are the module's, read from the signature pybind11 writes on the first line of
# its docstring (inspect.signature for the pure-Python parts); an enum member's value is the
# module's.
import ast
import inspect
from pathlib import Path

import pytest

import asperity
from asperity import batch, plot, topography

STUBS = Path(asperity.__file__).parent

# (stub file, the module it describes)
MODULES = [("__init__.pyi", asperity), ("topography.pyi", topography), ("batch.pyi", batch), ("plot.pyi", plot)]


def split_top_level(text, separator=","):
    """text split at `separator` outside brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            if c == quote and text[i - 1] != "\\":
                quote = None
        elif c in "'\"":
            quote = c
        elif c in "([{<":
            depth += 1
        elif c in ")]}>" and not (c == ">" and text[i - 1] == "-"):
            depth -= 1
        elif c == separator and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return [part.strip() for part in parts if part.strip()]


class Parameter:
    """A parameter as compared: its name, its kind (positional, keyword-only, *args, **kwargs), a default."""

    def __init__(self, name, kind, default):
        self.name, self.kind, self.default = name, kind, default

    def key(self):
        # *args and **kwargs compared by kind only (pybind11 names them args and kwargs)
        return (self.kind, None if self.kind in ("*", "**") else self.name, self.default)

    def __repr__(self):
        prefix = {"positional": "", "keyword": "*, ", "*": "*", "**": "**"}[self.kind]
        return prefix + self.name + ("=..." if self.default else "")


def pybind_signatures(function, name):
    """The parameters of each overload of a pybind11 function, from its docstring."""
    doc = function.__doc__ or ""
    lines = doc.splitlines()
    if lines and lines[0].startswith("Overloaded function"):
        heads = [line.split(". ", 1)[1] for line in lines if line[:1].isdigit() and ". " + name + "(" in line]
    else:
        heads = [lines[0]] if lines else []
    assert heads and all(head.startswith(name + "(") for head in heads), f"{name}: no signature in {doc[:80]!r}"
    signatures = []
    for head in heads:
        depth, end = 0, None
        for i, c in enumerate(head):  # the closing parenthesis of the parameter list
            if c == "(":
                depth += 1
            elif c == ")":
                depth -= 1
                if depth == 0:
                    end = i
                    break
        parameters, kind = [], "positional"
        for part in split_top_level(head[len(name) + 1:end]):
            if part == "*":
                kind = "keyword"
                continue
            if part.startswith("**"):
                parameters.append(Parameter(part[2:].split(":")[0].strip(), "**", False))
                continue
            if part.startswith("*"):
                parameters.append(Parameter(part[1:].split(":")[0].strip(), "*", False))
                kind = "keyword"
                continue
            name_and_default = split_top_level(part, "=")  # "name: type = default"
            parameters.append(Parameter(name_and_default[0].split(":")[0].strip(), kind, len(name_and_default) > 1))
        signatures.append(parameters)
    return signatures


def python_signature(function):
    """The parameters of a pure-Python function (inspect.signature)."""
    kinds = {inspect.Parameter.POSITIONAL_ONLY: "positional", inspect.Parameter.POSITIONAL_OR_KEYWORD: "positional",
             inspect.Parameter.KEYWORD_ONLY: "keyword", inspect.Parameter.VAR_POSITIONAL: "*",
             inspect.Parameter.VAR_KEYWORD: "**"}
    return [Parameter(p.name, kinds[p.kind], p.default is not inspect.Parameter.empty)
            for p in inspect.signature(function).parameters.values()]


def stub_signature(node):
    """The parameters of a stub's def."""
    args = node.args
    positional = args.posonlyargs + args.args
    defaults = [False] * (len(positional) - len(args.defaults)) + [True] * len(args.defaults)
    parameters = [Parameter(a.arg, "positional", d) for a, d in zip(positional, defaults)]
    if args.vararg:
        parameters.append(Parameter(args.vararg.arg, "*", False))
    parameters += [Parameter(a.arg, "keyword", d is not None) for a, d in zip(args.kwonlyargs, args.kw_defaults)]
    if args.kwarg:
        parameters.append(Parameter(args.kwarg.arg, "**", False))
    return parameters


def decorators(node):
    return {d.id if isinstance(d, ast.Name) else getattr(d, "attr", None) for d in node.decorator_list}


def signatures_of(function, name):
    """The module's signatures of a function or method (a list: pybind11 overloads)."""
    target = function
    if isinstance(target, (staticmethod, classmethod)):
        target = target.__func__
    if inspect.isfunction(target) or inspect.ismethod(target):
        return [python_signature(target)]
    return pybind_signatures(target, name)


def compare_function(where, name, stub_nodes, function, problems):
    """The stub's defs of one name (several with @overload) against the module's function."""
    module_signatures = signatures_of(function, name)
    module_keys = [[p.key() for p in s] for s in module_signatures]
    for node in stub_nodes:
        stub = stub_signature(node)
        if [p.key() for p in stub] not in module_keys:
            problems.append(f"{where}{name}: the stub's parameters {stub} are not the module's "
                            f"{' or '.join(map(str, module_signatures))}")


def public(names):
    return {name for name in names if not name.startswith("_")}


def stub_entries(body):
    """name -> the stub's nodes of that name (a def may come several times: @overload)."""
    entries = {}
    for node in body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            entries.setdefault(node.name, []).append(node)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            entries.setdefault(node.target.id, []).append(node)
        elif isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            entries.setdefault(node.targets[0].id, []).append(node)
        elif isinstance(node, ast.ImportFrom) and node.level == 1 and node.module is None:
            for alias in node.names:  # `from . import topography as topography`: a re-export (PEP 484)
                if alias.asname == alias.name:
                    entries.setdefault(alias.name, []).append(node)
    return entries


def module_names(module):
    """The public names a module holds (what it imports for its own use left out)."""
    if hasattr(module, "__all__"):
        names = set(module.__all__)
    else:
        names = {name for name, value in vars(module).items()
                 if not name.startswith("_") and getattr(value, "__module__", module.__name__) == module.__name__
                 and not inspect.ismodule(value)}
    return names | ({"__version__"} if hasattr(module, "__version__") else set())


def is_record(cls):
    return isinstance(cls, type) and issubclass(cls, tuple) and hasattr(cls, "_fields")


def compare_class(where, stub_class, cls, problems):
    entries = stub_entries(stub_class.body)
    if isinstance(cls, type) and issubclass(cls, BaseException):
        return  # the module's exceptions: stubs name the class only
    if is_record(cls):  # a namedtuple: its fields, in order
        fields = [name for name, nodes in entries.items() if isinstance(nodes[0], ast.AnnAssign)]
        if fields != list(cls._fields):
            problems.append(f"{where}: the stub's fields {fields} are not the record's {list(cls._fields)}")
        return
    if hasattr(cls, "__members__"):  # an enum (pybind11's or Python's): names and values
        stub_members = {}
        for name, nodes in entries.items():
            node = nodes[0]
            if isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant):
                stub_members[name] = node.value.value
        module_members = {name: int(member.value) if hasattr(member, "value") else int(member)
                          for name, member in cls.__members__.items()}
        if stub_members != module_members:
            problems.append(f"{where}: the stub's members {stub_members} are not the module's {module_members}")
        return
    # the public names, and the special methods a user calls (a constructor, copies, len())
    special = {"__init__", "__copy__", "__deepcopy__", "__len__"}
    bound = public(dir(cls)) | {name for name in special if name in vars(cls) and (
        name != "__init__" or (getattr(cls.__init__, "__doc__", "") or "").startswith("__init__("))}
    stubbed = public(entries) | (special & set(entries))
    for name in sorted(bound - stubbed):
        problems.append(f"{where}.{name}: in the module, not in the stub")
    for name in sorted(stubbed - bound):
        problems.append(f"{where}.{name}: in the stub, not in the module")
    for name, nodes in entries.items():
        if not hasattr(cls, name):
            continue  # named above
        attribute = inspect.getattr_static(cls, name)
        node = nodes[0]
        is_property = isinstance(attribute, property) or type(attribute).__name__ == "getset_descriptor"
        if isinstance(node, ast.AnnAssign) or (isinstance(node, ast.FunctionDef) and "property" in decorators(node)):
            if not is_property:
                problems.append(f"{where}.{name}: a property in the stub, not in the module")
            continue
        if isinstance(node, ast.FunctionDef):
            if is_property:
                problems.append(f"{where}.{name}: a method in the stub, a property in the module")
                continue
            static = isinstance(attribute, staticmethod)
            if ("staticmethod" in decorators(node)) != static:
                problems.append(f"{where}.{name}: static in one of the stub and the module only")
            compare_function(where + ".", name, nodes, getattr(cls, name), problems)


def check(stub_file, module, text=None):
    """The drift between a stub file (or `text` in its place) and the module, one line per problem."""
    tree = ast.parse(text if text is not None else (STUBS / stub_file).read_text())
    entries = stub_entries(tree.body)
    problems = []
    names = module_names(module)
    # module-level assignments the module does not hold are the stubs' own type aliases
    aliases = {name for name, nodes in entries.items() if isinstance(nodes[0], ast.Assign) and name not in names}
    aliases |= {name for name, nodes in entries.items()
                if isinstance(nodes[0], ast.AnnAssign) and isinstance(nodes[0].annotation, ast.Name)
                and nodes[0].annotation.id == "TypeAlias" and name not in names}
    # the stubs' own private types (_LawCurvesKeywords: a TypedDict for **kwargs), checked on their own
    aliases |= {name for name in entries if name.startswith("_") and name not in names}
    stubbed = set(entries) - aliases
    for name in sorted(names - stubbed):
        problems.append(f"{stub_file}: {name} is in the module, not in the stub")
    for name in sorted(stubbed - names):
        problems.append(f"{stub_file}: {name} is in the stub, not in the module")
    for name in sorted(stubbed & names):
        nodes, value = entries[name], getattr(module, name)
        node = nodes[0]
        if isinstance(node, ast.ClassDef):
            if not isinstance(value, type):
                problems.append(f"{stub_file}: {name} is a class in the stub, not in the module")
                continue
            compare_class(f"{stub_file}: {name}", node, value, problems)
        elif isinstance(node, ast.FunctionDef):
            if isinstance(value, type) or not callable(value):
                problems.append(f"{stub_file}: {name} is a function in the stub, not in the module")
                continue
            compare_function(f"{stub_file}: ", name, nodes, value, problems)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.annotation, ast.Name):
            expected = {"int": int, "float": float, "str": str, "bool": bool}.get(node.annotation.id)
            if expected and not isinstance(value, expected):
                problems.append(f"{stub_file}: {name} is a {node.annotation.id} in the stub, "
                                f"a {type(value).__name__} in the module")
    return problems


@pytest.mark.parametrize("stub_file,module", MODULES, ids=[stub for stub, _ in MODULES])
def test_stub_matches_module(stub_file, module):
    problems = check(stub_file, module)
    assert not problems, "\n".join(problems)


def test_the_check_finds_drift():
    # a parameter renamed, an enum member missing, a name the module lacks: each caught
    text = (STUBS / "__init__.pyi").read_text()
    changes = [("def order_of(twice_order: OrderLike)", "def order_of(order: OrderLike)", "order_of"),
               ("    avx512 = 3\n", "", "InstructionSet"),
               ("gw_area_fraction_limit: float", "gw_area_limit: float", "gw_area_limit")]
    for old, new, named in changes:
        assert old in text
        problems = "\n".join(check("__init__.pyi", asperity, text.replace(old, new)))
        assert named in problems, (old, problems)


def test_law_curves_keywords_are_the_modules():
    """The stub's _LawCurvesKeywords (law_curves' **kwargs) names the module's keywords, with their types."""
    tree = ast.parse((STUBS / "__init__.pyi").read_text())
    stub_class = next(node for node in tree.body if isinstance(node, ast.ClassDef) and node.name == "_LawCurvesKeywords")
    stub = {node.target.id: ast.unparse(node.annotation) for node in stub_class.body if isinstance(node, ast.AnnAssign)}
    python_type = {"float": "float", "str": "str", "pair": "Tuple[float, float]"}
    assert stub == {key: python_type[kind] for key, kind in asperity.law_curves_keywords.items()}
