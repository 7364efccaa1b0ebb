"""Relations between a study's parameters: arithmetic expressions of other parameters'
names ("2 * span", "atan(dy / dx) * 180 / pi"), evaluated without Python's eval."""
from __future__ import annotations

import ast
import math
import operator
from typing import Callable, Dict, List, Set

_OPERATORS: Dict[type, Callable[..., float]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
    ast.Pow: operator.pow, ast.Mod: operator.mod, ast.USub: operator.neg, ast.UAdd: operator.pos,
}
_FUNCTIONS: Dict[str, Callable[..., float]] = {
    name: getattr(math, name) for name in ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt", "exp",
                                           "log", "radians", "degrees", "hypot")
}
_FUNCTIONS.update({"abs": abs, "min": min, "max": max})
_CONSTANTS = {"pi": math.pi, "e": math.e}


class Relation:
    """A parameter's value as an expression of other parameters."""

    def __init__(self, text: str, owner: str) -> None:
        self.text = text
        try:
            self._tree = ast.parse(text, mode="eval").body
        except SyntaxError as error:
            raise ValueError(f"parameter {owner}: relation '{text}' is not an expression ({error.msg})") from None
        self.names: Set[str] = set()
        self._check(self._tree, owner)

    def _check(self, node: ast.AST, owner: str) -> None:
        if isinstance(node, ast.Name):
            if node.id not in _CONSTANTS:
                self.names.add(node.id)
        elif isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            pass
        elif isinstance(node, (ast.BinOp, ast.UnaryOp)) and type(node.op) in _OPERATORS:
            for child in ast.iter_child_nodes(node):
                if not isinstance(child, ast.operator) and not isinstance(child, ast.unaryop):
                    self._check(child, owner)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _FUNCTIONS:
            for argument in node.args:
                self._check(argument, owner)
        else:
            raise ValueError(f"parameter {owner}: relation '{self.text}' may hold numbers, parameter names, "
                             f"+ - * / ** % and {', '.join(sorted(_FUNCTIONS))} only")

    def __call__(self, values: Dict[str, float]) -> float:
        return float(self._evaluate(self._tree, values))

    def _evaluate(self, node: ast.AST, values: Dict[str, float]) -> float:
        if isinstance(node, ast.Name):
            return _CONSTANTS[node.id] if node.id in _CONSTANTS else values[node.id]
        if isinstance(node, ast.Constant):
            return float(node.value)
        if isinstance(node, ast.BinOp):
            return _OPERATORS[type(node.op)](self._evaluate(node.left, values), self._evaluate(node.right, values))
        if isinstance(node, ast.UnaryOp):
            return _OPERATORS[type(node.op)](self._evaluate(node.operand, values))
        assert isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
        return _FUNCTIONS[node.func.id](*(self._evaluate(argument, values) for argument in node.args))


def evaluation_order(relations: Dict[str, Relation], known: Set[str]) -> List[str]:
    """The related parameters in an order in which each one's names are known before it.
    Raises ValueError on a name that is no parameter, or on a cycle."""
    order: List[str] = []
    done = set(known)
    pending = dict(relations)
    while pending:
        ready = [name for name, relation in pending.items() if relation.names <= done]
        if not ready:
            name, relation = next(iter(pending.items()))
            unknown = relation.names - done - set(pending)
            if unknown:
                raise ValueError(f"parameter {name}: relation '{relation.text}' names no parameter "
                                 f"{', '.join(sorted(unknown))}")
            raise ValueError(f"parameters {', '.join(sorted(pending))}: their relations depend on each other in a cycle")
        for name in sorted(ready):
            order.append(name)
            done.add(name)
            del pending[name]
    return order
