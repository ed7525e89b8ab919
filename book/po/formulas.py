#!/usr/bin/env python3
"""The book's formulas, kept whole through the translation (two mdBook preprocessors).

mdbook-gettext rebuilds every chapter it translates from its Markdown events, and
Markdown takes TeX apart: `t\\,d` loses its backslash, `[X]` gains two, a line that
starts with `-` is escaped. `hide` (before gettext, and before the xgettext renderer
extracts the messages) turns each formula into a code span, which Markdown keeps as
it is: `$O + t\\,d$` becomes `` `$O + t\\,d$` `` (a formula written on several lines
is joined into one); `show` (after gettext, before katex) turns those spans back
into formulas. A formula is found where mdbook-katex finds it: `$$...$$` or `$...$`
outside code spans and fenced code, a backslash escaping the next character.

Both do nothing to an English book (no po/LANG.po for book.language), so it is
exactly what mdBook and mdbook-katex make without them.

    python3 po/formulas.py hide|show     # as mdBook runs them, from book/
"""

import json
import os
import re
import sys

# A code span whose text is a formula, dollars included: what `hide` writes.
HIDDEN = re.compile(r"(?<!`)(`+)(\$[^`]*\$)\1(?!`)")


def formulas(text):
    """The (start, end) of each formula of `text`, its delimiters included, found
    as mdbook-katex's scanner finds them."""
    found, i, n = [], 0, len(text)
    while i < n:
        if text[i] == "$":
            delimiter = "$$" if text.startswith("$$", i) else "$"
            start, j = i, i + len(delimiter)
            while True:
                j = text.find(delimiter, j)
                if j < 0:
                    return found
                backslashes = len(text[:j]) - len(text[:j].rstrip("\\"))
                if backslashes % 2 == 0:
                    break
                j += len(delimiter)
            found.append((start, j + len(delimiter)))
            i = j + len(delimiter)
        elif text[i] == "\\":
            i += 2
        elif text[i] == "`":
            run = len(text[i:]) - len(text[i:].lstrip("`"))
            j = i + run
            while True:
                j = text.find("`" * run, j)
                if j < 0:
                    return found
                j += run
                if j < n and text[j] == "`":
                    j = len(text) - len(text[j:].lstrip("`"))
                else:
                    break
            i = j
        else:
            i += 1
    return found


def hide(text, where):
    """`text` with each formula made a code span."""
    if HIDDEN.search(text):
        sys.exit(
            f"{where}: a code span `$...$` would be taken for a hidden formula: "
            "write it another way"
        )
    out, last = [], 0
    for start, end in formulas(text):
        formula = text[start:end]
        if "`" in formula:
            sys.exit(f"{where}: a formula holds a backtick: {formula}")
        out += [text[last:start], "`", " ".join(formula.split("\n")), "`"]
        last = end
    return "".join(out + [text[last:]])


def show(text, where):
    """`text` with each code span that holds a formula made that formula."""
    return HIDDEN.sub(lambda m: m.group(2), text)


def chapters(item, change):
    """Applies `change` to the content of every chapter under `item`."""
    if isinstance(item, dict):
        chapter = item.get("Chapter")
        if isinstance(chapter, dict) and isinstance(chapter.get("content"), str):
            chapter["content"] = change(chapter["content"], chapter.get("path") or chapter["name"])
        for value in item.values():
            chapters(value, change)
    elif isinstance(item, list):
        for value in item:
            chapters(value, change)


def translated(context):
    """Whether mdbook-gettext translates this build: the xgettext renderer's
    messages, or a book.language with its po/LANG.po."""
    if context.get("renderer") == "xgettext":
        return True
    language = context["config"].get("book", {}).get("language")
    return bool(language) and os.path.exists(os.path.join(context["root"], "po", f"{language}.po"))


def main():
    mode = sys.argv[1:2]
    if len(sys.argv) > 2 and sys.argv[2] == "supports":
        return
    if mode not in (["hide"], ["show"]):
        sys.exit("usage: formulas.py hide|show")
    context, book = json.load(sys.stdin)
    if translated(context):
        chapters(book, hide if mode == ["hide"] else show)
    json.dump(book, sys.stdout)


if __name__ == "__main__":
    main()
