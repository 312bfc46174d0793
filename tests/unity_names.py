#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The unity build's hazard of file-local names (CMakeLists.txt, "A unity build").

A unity build compiles each batch of .cpp files as one translation unit, in the order CMake lists
them (build/CMakeFiles/TARGET.dir/Unity/unity_N_cxx.cxx). A name a file keeps to itself (declared
in an anonymous namespace, `static`, or a namespace-scope const variable; a using-directive at
namespace scope lends the names of its namespace the same way) is then seen by every later file
of its batch, and by the project headers those files are the first to include:
  - two files of a batch declaring the same file-local name: a redefinition, or two overloads
    where each file had meant its own;
  - a later file (or a header it is the first to include) naming it unqualified, as `floor(x)`
    for std::floor beside an earlier file's floor(double): the call may take the earlier file's.
Prints every such pair and exits 1; 0 when there is none.

The batches are CMake's own: those of BUILD_DIR when it is a unity build, else those of a unity
configuration of SOURCE_DIR generated (not built) into BUILD_DIR/unity_names, so that the test
reads the batches the unity build (scripts/test, scripts/sanitize) compiles whichever way this
build is configured. The sources are read as tokens (comments, strings and preprocessor lines
dropped), not compiled: a name counts as used unqualified wherever it is written without `::`,
`.` or `->` before it and not as a declaration, unless the using file declares it in a class or a
function (a member, a local, a parameter) or a project header it includes declares it as a class
member: these hide the earlier file's name. Not seen: a name met through a macro, or through a
template of an earlier file instantiated later.

Usage: unity_names.py SOURCE_DIR BUILD_DIR [CMAKE]
"""
import os
import re
import subprocess
import sys
from pathlib import Path

TOKEN = re.compile(
    r"""(?P<pp>(?:\A|(?<=\n))[ \t]*\#(?:[^\n\\]|\\.)*)
      | (?P<ws>\s+)
      | (?P<comment>//[^\n]*|/\*.*?\*/)
      | (?P<raw>(?:u8|u|U|L)?R"(?P<delim>[^(\s]*)\(.*?\)(?P=delim)")
      | (?P<str>(?:u8|u|U|L)?"(?:[^"\\\n]|\\.)*")
      | (?P<chr>(?:u8|u|U|L)?'(?:[^'\\\n]|\\.)*')
      | (?P<num>\.?\d(?:[\w.]|'(?=\w)|[eEpP][+-])*)
      | (?P<id>[A-Za-z_]\w*)
      | (?P<op>::|->|.)""",
    re.VERBOSE | re.DOTALL,
)
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"', re.MULTILINE)

# Words that are not names a file declares or uses.
KEYWORDS = set("""alignas alignof and asm auto bool break case catch char char16_t char32_t class const constexpr
const_cast continue decltype default delete do double dynamic_cast else enum explicit export extern false float for
friend goto if inline int long mutable namespace new noexcept not nullptr operator or private protected public register
reinterpret_cast return short signed sizeof static static_assert static_cast struct switch template this thread_local
throw true try typedef typeid typename union unsigned using virtual void volatile wchar_t while final
override""".split())
SPECIFIERS = {"static", "inline", "constexpr", "const", "extern", "thread_local", "volatile", "mutable", "friend"}


def tokens(text):
    """(kind, text, line) of every token but blanks, comments and preprocessor lines, literals as 'lit'; and
    whether each token is glued to the one before (no blank between)."""
    out, glued, line, blank = [], [], 1, True
    for m in TOKEN.finditer(text):
        kind = m.lastgroup if m.lastgroup != "delim" else "raw"
        if kind in ("id", "op", "raw", "str", "chr", "num"):
            out.append((kind if kind in ("id", "op") else "lit", m.group(), line))
            glued.append(not blank)
        blank = kind in ("ws", "comment", "pp")
        line += m.group().count("\n")
    return out, glued


class Scan:
    """What one file declares at namespace scope, and which names it writes unqualified."""

    def __init__(self, path):
        self.path = path
        self.local = {}  # file-local name -> line
        self.declared = {}  # namespace path (tuple) -> names declared there, file-local or not
        self.directives = []  # (namespace path, target as written) of namespace-scope using-directives
        self.uses = {}  # name written unqualified -> first line
        self.hiding = set()  # names it declares in a class or a function: members, locals, parameters
        self.members = set()  # names it declares as class members (which hide in the class's member functions)
        self.variable = None  # set by decide() for a variable's statement
        self.walk(*tokens(Path(path).read_text(encoding="utf-8", errors="replace")))

    def walk(self, toks, glued):
        scopes = []  # ('ns', name) / ('anon', None) / ('block', None) / ('enum', None) / ('class', parentheses)
        stmt, decided, ends_with_body = [], False, False
        parentheses = 0  # open ( before the token
        for i, (kind, text, line) in enumerate(toks):
            parentheses += 1 if text == "(" else -1 if text == ")" else 0
            prev = toks[i - 1][1] if i > 0 else ""
            nxt = toks[i + 1][1] if i + 1 < len(toks) else ""
            at_namespace = all(s[0] in ("ns", "anon") for s in scopes)
            if kind == "id" and text not in KEYWORDS:
                declared = self.declarator(toks, glued, i)
                if not declared and prev not in ("::", ".", "->"):
                    self.uses.setdefault(text, line)
                if declared and (not at_namespace or self.depth(stmt) > 0):
                    self.hiding.add(text)
                    if scopes and scopes[-1][0] == "class" and parentheses == scopes[-1][1]:
                        self.members.add(text)
            if not at_namespace:
                if scopes[-1][0] == "enum" and kind == "id" and prev in ("{", ",") and nxt in (",", "=", "}"):
                    self.declare(scopes, text, line)
                if text == "{":
                    scopes.append(("block", None))
                elif text == "}":
                    scopes.pop()
                    if all(s[0] in ("ns", "anon") for s in scopes) and ends_with_body:
                        stmt, decided, ends_with_body = [], False, False
                continue
            if text == ";":
                if stmt and not decided:
                    self.decide(scopes, stmt)
                stmt, decided, ends_with_body = [], False, False
            elif text == "{":
                words = [t[1] for t in stmt]
                if "namespace" in words[:2]:
                    names = [w for w in words[words.index("namespace") + 1 :] if w != "::"]
                    scopes.append(("ns", "::".join(names)) if names else ("anon", None))
                    stmt, decided = [], False
                elif words[:1] == ["extern"] and len(stmt) == 2 and stmt[1][0] == "lit":
                    scopes.append(("ns", ""))  # extern "C" { ... }: the same namespace
                    stmt, decided = [], False
                else:
                    what = self.decide(scopes, stmt) if not decided else None
                    decided = True
                    ends_with_body = ends_with_body or what == "function"
                    scopes.append({"enum": ("enum", None), "class": ("class", parentheses)}.get(what, ("block", None)))
            elif text == "}":
                if scopes:
                    scopes.pop()
                stmt, decided, ends_with_body = [], False, False
            elif text == "=" and not decided and self.depth(stmt) == 0 and self.template_closed(stmt):
                self.decide(scopes, stmt)
                decided = True
            elif text == "," and decided and self.depth(stmt) == 0 and self.variable is not None:
                # int a = 1, b = 2;: the next declarator of the same statement
                if nxt and toks[i + 1][0] == "id" and i + 2 < len(toks) and toks[i + 2][1] in ("=", "{", ";", ","):
                    self.declare(scopes, nxt, toks[i + 1][2], file_local=self.variable)
            else:
                stmt.append((kind, text, line))

    @staticmethod
    def template_closed(stmt):
        """False inside template <...>'s parameters, whose = is a default argument."""
        if not stmt or stmt[0][1] != "template":
            return True
        return sum(1 if t[1] == "<" else -1 if t[1] == ">" else 0 for t in stmt) <= 0

    @staticmethod
    def depth(stmt):
        return sum(1 if t[1] == "(" else -1 if t[1] == ")" else 0 for t in stmt)

    @staticmethod
    def declarator(toks, glued, i):
        """Whether toks[i] is declared there: after a type and before = ; , ) { ( [ :. A type is a name, a
        template's > or a * or & written as the sources write them, glued to the type (`double* p`,
        `const T& x`, `T&& y`; `a * b` and `a && b` are expressions: clang-format, .clang-format)."""
        if i == 0 or i + 1 >= len(toks) or toks[i + 1][1] not in ("=", ";", ",", ")", "{", "(", "[", ":"):
            return False
        kind, prev, _ = toks[i - 1]
        if kind == "id":
            return prev not in ("return", "case", "throw", "else", "do", "new", "delete", "sizeof", "not", "and",
                                "or", "using", "namespace", "goto", "co_return", "co_yield", "co_await")
        if prev == ">":
            return glued[i - 1]
        if prev in ("*", "&"):
            k = i - 1
            while k > 0 and toks[k - 1][1] in ("*", "&") and glued[k]:
                k -= 1
            return glued[k]
        return False

    def declare(self, scopes, name, line, file_local=None):
        path = tuple(s[1] if s[0] == "ns" else "" for s in scopes if s[0] in ("ns", "anon"))
        self.declared.setdefault(path, set()).add(name)
        anonymous = any(s[0] == "anon" for s in scopes)
        if file_local or anonymous:
            self.local.setdefault(name, line)

    def decide(self, scopes, stmt):
        """Records the name a namespace-scope statement declares; returns 'function', 'enum', 'class' or None."""
        self.variable = None  # a variable's statement: whether its declarators are file-local
        toks = list(stmt)
        while toks and toks[0][1] == "template":  # template <...>: its parameters are not the file's names
            toks, angle = toks[1:], 0
            while toks:
                angle += 1 if toks[0][1] == "<" else -1 if toks[0][1] == ">" else 0
                toks = toks[1:]
                if angle == 0:
                    break
        words = [t[1] for t in toks]
        lead = set()
        while words and (words[0] in SPECIFIERS or words[0] == "["):
            if words[0] == "[":  # [[attribute]]
                close = words.index("]") + 2 if "]" in words else len(words)
                toks, words = toks[close:], words[close:]
                continue
            lead.add(words[0])
            toks, words = toks[1:], words[1:]
        if not words:
            return None
        if words[0] in ("struct", "class", "union", "enum"):
            rest = toks[2:] if words[0] == "enum" and words[1:2] in (["class"], ["struct"]) else toks[1:]
            if rest and rest[0][0] == "id" and rest[0][1] not in KEYWORDS:
                self.declare(scopes, rest[0][1], rest[0][2])
            return "enum" if words[0] == "enum" and toks[1:2] == rest[:1] else "class"
        if words[0] == "using":
            if words[1:2] == ["namespace"]:
                self.directives.append((tuple(s[1] if s[0] == "ns" else "" for s in scopes if s[0] != "block"),
                                        "".join(words[2:])))
            elif len(words) == 2 or words[2:3] == ["="]:  # using alias = ... (decided at its =)
                self.declare(scopes, words[1], toks[1][2])
            return None
        if words[0] in ("typedef", "static_assert", "namespace"):
            if words[0] == "typedef":
                names = [t for t in toks if t[0] == "id" and t[1] not in KEYWORDS]
                if names:
                    self.declare(scopes, names[-1][1], names[-1][2])
            return None
        # A function (the name before the first `(` that is not decltype's) or a variable (the last name
        # before = { ; [ or that `(`).
        skip = 0
        for j, (kind, text, line) in enumerate(toks):
            if skip:
                skip += 1 if text == "(" else -1 if text == ")" else 0
                continue
            if kind == "id" and text in ("decltype", "alignas", "noexcept", "sizeof", "__attribute__"):
                skip = -1  # until its parentheses close
                continue
            if skip < 0:
                skip = 1 if text == "(" else skip
                continue
            if text == "(":
                name = toks[j - 1] if j > 0 else None
                if not name or name[0] != "id" or name[1] in KEYWORDS:
                    return None  # an operator, a function pointer: not a plain name
                if j > 1 and toks[j - 2][1] in ("::", "operator", "~"):
                    return "function"  # a member or a namespace's function defined here: not a new name
                self.declare(scopes, name[1], name[2], file_local="static" in lead)
                return "function"
            if text in ("[", "{"):
                break
        names = [t for t in toks if t[0] == "id" and t[1] not in KEYWORDS]
        if not names:
            return None
        before = toks[toks.index(names[-1]) - 1][1] if toks.index(names[-1]) > 0 else ""
        if before == "::":
            return None  # a static member or a namespace's variable defined here
        const = bool(lead & {"static", "const", "constexpr"}) or "const" in words[-3:]
        self.variable = const and not lead & {"inline", "extern"}
        self.declare(scopes, names[-1][1], names[-1][2], file_local=self.variable)
        return None


def headers(path, roots, cache):
    """The project headers `path` includes, directly or not, each once, in order."""
    out = []

    def visit(p):
        for name in INCLUDE.findall(Path(p).read_text(encoding="utf-8", errors="replace")):
            for base in [Path(p).parent] + roots:
                h = (base / name).resolve()
                if h.is_file():
                    if h not in cache:
                        cache.add(h)
                        out.append(h)
                        visit(h)
                    break

    visit(path)
    return out


def unity_batches(source_dir, build_dir, cmake):
    """{unity file: [sources in order]} of the unity build of source_dir (its own when build_dir is one)."""
    cache_file = build_dir / "CMakeCache.txt"
    cache = cache_file.read_text(errors="replace") if cache_file.is_file() else ""
    scratch = build_dir / "unity_names"
    if re.search(r"^CMAKE_UNITY_BUILD:\w+=(ON|1|TRUE|YES|Y)$", cache, re.MULTILINE | re.IGNORECASE):
        found = [u for u in build_dir.glob("**/CMakeFiles/*.dir/Unity/unity_*_cxx.cxx") if scratch not in u.parents]
    else:
        # Generated, not compiled: a few seconds, CMake's own batches (sources with their own compile
        # definitions, as io/output.cpp, or SKIP_UNITY_BUILD_INCLUSION stay out of them).
        run = subprocess.run([cmake, "-S", str(source_dir), "-B", str(scratch), "-DCMAKE_UNITY_BUILD=ON",
                              "-DBUILD_TESTING=OFF"], capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout + run.stderr)
            sys.exit("FAIL: cannot generate the unity configuration in " + str(scratch))
        found = scratch.glob("**/CMakeFiles/*.dir/Unity/unity_*_cxx.cxx")
    return {u: [Path(f) for f in re.findall(r'#include "([^"]+)"', u.read_text())] for u in sorted(found)}


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    source_dir, build_dir = Path(argv[1]).resolve(), Path(argv[2]).resolve()
    cmake = argv[3] if len(argv) > 3 else "cmake"
    roots = [source_dir / "include", source_dir / "src", source_dir / "python"]
    batches = unity_batches(source_dir, build_dir, cmake)
    scans = {}

    def scan(p):
        if p not in scans:
            scans[p] = Scan(p)
        return scans[p]

    # Every namespace a using-directive may name: its names as the project's headers declare them.
    namespaces = {}
    for h in list(source_dir.glob("include/**/*.hpp")) + list(source_dir.glob("src/**/*.hpp")):
        for path, names in scan(h.resolve()).declared.items():
            namespaces.setdefault("::".join(p for p in path if p), set()).update(names)

    def shown(path):
        return os.path.relpath(path, source_dir)

    problems, files, names = [], 0, 0
    for unity, sources in batches.items():
        batch = f"{unity.parent.parent.name[:-4]} {unity.stem}"
        seen_headers = set()
        earlier = []  # (file, its lent names {name: line})
        for src in sources:
            files += 1
            s = scan(src.resolve())
            # The file and the headers it is the first of its batch to include are read after the earlier
            # files; a member, local or parameter of that name in the file, or a member in any header it
            # includes, hides theirs.
            users = [(src, s)] + [(h, scan(h)) for h in headers(src, roots, seen_headers)]
            hiding = set(s.hiding).union(*(scan(h).members for h in headers(src, roots, set())))
            lent = dict(s.local)
            for _, target in s.directives:
                for ns, declared in namespaces.items():
                    if ns == target or ns.endswith("::" + target):
                        for n in declared:
                            lent.setdefault(n, 0)
            names += len(s.local)
            for other, other_lent in earlier:
                for name, line in sorted(s.local.items()):
                    if name in other_lent:
                        problems.append(f"{batch}: `{name}` is file-local in {shown(other)} and in "
                                        f"{shown(src)}:{line}")
                for name in sorted(other_lent):
                    if name in s.local or name in hiding:
                        continue  # reported above; hidden where it is written
                    for user, u in users:
                        if name in u.uses:
                            problems.append(f"{batch}: `{name}`, file-local in {shown(other)}, is "
                                            f"written unqualified in {shown(user)}:{u.uses[name]}, "
                                            f"after it in the batch")
            earlier.append((src, lent))
    if files == 0 or names == 0:
        print(f"FAIL: {len(batches)} unity batches, {files} files, {names} file-local names: nothing was read")
        return 1
    for p in problems:
        print("FAIL: " + p)
    if problems:
        print("A file-local name wants a name of its own (or its file compiled alone: SKIP_UNITY_BUILD_INCLUSION, "
              "CMakeLists.txt).")
    print(f"{'FAIL' if problems else 'ok'}: {len(batches)} unity batches, {files} files, {names} file-local names, "
          f"{len(problems)} clashes")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
