"""Words in code: the string literals of a module that are prose, found by one rule that
benchmarks/words_audit.py counts and tests/test_layers.py holds the model check to."""

import ast


def prose(tree: ast.Module) -> list[tuple[int, str]]:
    """The string literals and f-strings of a module with a space and over 20 characters of
    literal text (an f-string's pieces counted as one), docstrings left out: (line, text)."""
    docs: set[int] = set()
    pieces: set[int] = set()
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        for st in body if isinstance(body, list) else []:
            if (
                isinstance(st, ast.Expr)
                and isinstance(st.value, ast.Constant)
                and isinstance(st.value.value, str)
            ):
                docs.add(id(st.value))
        if isinstance(node, ast.JoinedStr):
            pieces.update(id(v) for v in node.values)
    out = []
    for node in ast.walk(tree):
        text = None
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            if id(node) not in docs and id(node) not in pieces:
                text = node.value
        elif isinstance(node, ast.JoinedStr):
            text = "".join(v.value if isinstance(v, ast.Constant) else "{}" for v in node.values)
        if text is not None and len(text) > 20 and " " in text:
            out.append((node.lineno, text))
    return out
