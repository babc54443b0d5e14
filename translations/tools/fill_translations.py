#!/usr/bin/env python3
"""Puts translations/learnid_de.ts and learnid_zh_CN.ts in their final form after lupdate.

`cmake --build <dir> --target update_translations` runs lupdate over core/, ui/ and app/ and then
this script (by hand: python3 translations/tools/fill_translations.py). It
 1. files each text under the context the code looks it up in. Most of core/ and the
    command-line tools translate through a file-local helper,
        QString tr(const char *text) { return QCoreApplication::translate("ScenarioFile", text); }
    which lupdate cannot see through: it files the texts under the enclosing namespace or class
    ("learnid", "learnid::cli") and warns "lacks Q_OBJECT macro". Such a text is moved, by the
    file lupdate found it in, to the context of that file's helper;
 2. drops the source locations (lupdate writes them for step 1 only);
 3. fills every translation from the tables in texts_*.py (source -> (German, Chinese)). The
    tables are where translations live: lupdate forgets those of step 1 on every run.
The tables are checked first: a translation whose %1, %2 ... (or %n) differ from the source's,
whose closing punctuation, leading/trailing blanks or line breaks differ, is refused and nothing is
written. Texts without a table entry stay unfinished and are listed; tests/app/tst_translations
fails until they are translated. Exit status 1 on a refused entry or a text without context.
"""
import os
import re
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, '..', '..'))
sys.path.insert(0, HERE)
import texts_app  # noqa: E402
import texts_can  # noqa: E402
import texts_core  # noqa: E402
import texts_ui  # noqa: E402

LANGUAGES = (('de', 0), ('zh_CN', 1))
TABLES = (texts_ui, texts_core, texts_can, texts_app)

# --- the tables, checked --------------------------------------------------------------------------

FULL_WIDTH = '（）：，。；！？“”'
CLOSING = {'.': '.。', ':': ':：', '?': '?？', '!': '!！', '…': '…', ';': ';；'}


def placeholders(text):
    return sorted(set(re.findall(r'%L?(\d+|n)', text)))


def problems(source, translation):
    """What the translation fails to keep of the source, as a list of reasons."""
    found = []
    if placeholders(source) != placeholders(translation):
        found.append(f'placeholders {placeholders(source)} became {placeholders(translation)}')
    last = source.rstrip()[-1:] if source.strip() else ''
    if last in CLOSING and translation.rstrip()[-1:] not in CLOSING[last]:
        found.append(f'ends without {last!r}')
    if source.count('\n') != translation.count('\n'):
        found.append('line breaks differ')
    # A blank that joins the text to its neighbour is kept, except next to full-width
    # punctuation, which brings its own space: ' (abort code %1)' -> '（中止代码 %1）'.
    lead = lambda s: s[:len(s) - len(s.lstrip())]
    trail = lambda s: s[len(s.rstrip()):]
    if lead(source) != lead(translation) and translation[:1] not in FULL_WIDTH:
        found.append('leading blanks differ')
    if trail(source) != trail(translation) and translation[-1:] not in FULL_WIDTH:
        found.append('trailing blanks differ')
    return found


def load_tables():
    singular, plural, refused = {}, {}, []
    for table in TABLES:
        for source, pair in table.T.items():
            if source in singular and singular[source] != pair:
                refused.append(f'{source!r}: two different entries ({table.__name__})')
            singular[source] = pair
            for (lang, col) in LANGUAGES:
                for why in problems(source, pair[col]):
                    refused.append(f'{lang}: {source!r} -> {pair[col]!r}: {why}')
        for source, forms in getattr(table, 'PLURAL', {}).items():
            plural[source] = forms
            for (lang, col) in LANGUAGES:
                for form in forms[col]:
                    for why in problems(source, form):
                        refused.append(f'{lang}: {source!r} -> {form!r}: {why}')
    return singular, plural, refused


# --- step 1: contexts -------------------------------------------------------------------------

HELPER = re.compile(r'translate\(\s*"([^"]+)"\s*,\s*[A-Za-z_]\w*\s*\)')
LITERAL_CONTEXT = re.compile(r'(?:translate|QT_TRANSLATE_NOOP3?|QT_TRANSLATE_N_NOOP3?)\(\s*"([^"]+)"')
TR_CLASS = re.compile(r'\b(?:class|struct)\s+(?:\w+\s+)?(\w+)\b[^;{()]*\{(.*?)\n\};', re.S)


class Sources:
    """What the sources say about translation contexts."""

    def __init__(self):
        self.helper = {}  # file -> the context its tr() helper passes
        self.literal = set()  # contexts the code names: translate("X", ...), QT_TRANSLATE_NOOP
        self.classes = set()  # classes with their own tr(): Q_OBJECT, Q_DECLARE_TR_FUNCTIONS
        for folder in ('core', 'ui', 'app'):
            for base, _, names in os.walk(os.path.join(ROOT, folder)):
                for name in names:
                    if name.endswith(('.cpp', '.h')):
                        self._read(os.path.join(base, name))

    def _read(self, path):
        text = open(path, encoding='utf-8').read()
        helpers = set(HELPER.findall(text))
        if len(helpers) == 1:
            self.helper[path] = helpers.pop()
        self.literal.update(LITERAL_CONTEXT.findall(text))
        self.literal.update(re.findall(r'Q_DECLARE_TR_FUNCTIONS\((\w+)\)', text))
        for name, body in TR_CLASS.findall(text):
            if 'Q_OBJECT' in body:
                self.classes.add(name)

    def is_real(self, context):
        # lupdate names a Q_OBJECT class's context with its namespaces: learnid::MainWindow
        return context in self.literal or context.split('::')[-1] in self.classes

    def target(self, context, files):
        """The contexts a text found in `files` under `context` is looked up in at run time."""
        if self.is_real(context):
            return [context]
        targets = [self.helper.get(f) for f in files]
        return None if not files or None in targets else sorted(set(targets))


def refile(root, ts_dir, sources):
    """Step 1 and 2: {context: [message]} with texts under their run-time context, no locations."""
    contexts, unplaced = {}, []
    for ctx in root.iter('context'):
        name = ctx.findtext('name')
        for msg in ctx.iter('message'):
            files = [os.path.normpath(os.path.join(ts_dir, loc.get('filename')))
                     for loc in msg.findall('location') if loc.get('filename')]
            for loc in msg.findall('location'):
                msg.remove(loc)
            targets = sources.target(name, files)
            if targets is None:
                unplaced.append(f'{msg.findtext("source")!r} (context {name}, in {files})')
                targets = [name]
            for target in targets:
                into = contexts.setdefault(target, {})
                key = (msg.findtext('source'), msg.findtext('comment'))
                if key not in into:
                    into[key] = msg
    return contexts, unplaced


# --- step 3: translations -----------------------------------------------------------------------

def fill(msg, col, singular, plural):
    """Fills msg's translation; False if the tables have none."""
    src = msg.findtext('source') or ''
    tr = msg.find('translation')
    if msg.get('numerus') == 'yes':
        if src not in plural:
            return False
        for form in list(tr):
            tr.remove(form)
        for text in plural[src][col]:
            ET.SubElement(tr, 'numerusform').text = text
        tr.text = None
    elif src in singular:
        tr.text = singular[src][col]
    elif src.startswith(('Ctrl+', 'Shift+')):  # key sequences stay as they are in every language
        tr.text = src
    else:
        return False
    tr.attrib.pop('type', None)
    return True


# --- writing, in lupdate's layout ---------------------------------------------------------------

def escape(text):
    return (text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')
            .replace('"', '&quot;').replace("'", '&apos;'))


def element(e, indent):
    attrs = ''.join(f' {k}="{escape(v)}"' for k, v in e.attrib.items())
    pad = ' ' * indent
    if len(e) == 0:
        return f'{pad}<{e.tag}{attrs}>{escape(e.text or "")}</{e.tag}>\n'
    inner = ''.join(element(child, indent + 4) for child in e)
    return f'{pad}<{e.tag}{attrs}>\n{inner}{pad}</{e.tag}>\n'


def write(path, root, contexts):
    attrs = ''.join(f' {k}="{v}"' for k, v in root.attrib.items())
    with open(path, 'w', encoding='utf-8') as f:
        f.write(f'<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n<TS{attrs}>\n')
        for name in sorted(contexts):
            f.write(f'<context>\n    <name>{escape(name)}</name>\n')
            for msg in contexts[name].values():
                f.write(element(msg, 4))
            f.write('</context>\n')
        f.write('</TS>\n')


def main():
    singular, plural, refused = load_tables()
    if refused:
        print('fill_translations: refused, nothing written:\n  ' + '\n  '.join(refused))
        return 1
    sources = Sources()
    status = 0
    used = set()
    for lang, col in LANGUAGES:
        path = os.path.join(HERE, '..', f'learnid_{lang}.ts')
        root = ET.parse(path).getroot()
        contexts, unplaced = refile(root, os.path.dirname(path), sources)
        for text in unplaced:
            print(f'{lang}: no translation context for {text}: give the file a tr() helper or a '
                  'Q_OBJECT / Q_DECLARE_TR_FUNCTIONS class')
            status = 1
        missing = total = 0
        for msgs in contexts.values():
            for msg in msgs.values():
                total += 1
                if fill(msg, col, singular, plural):
                    used.add(msg.findtext('source'))
                elif msg.find('translation').get('type') == 'unfinished':
                    missing += 1
                    print(f'{lang}: no translation for {msg.findtext("source")!r}')
        write(path, root, contexts)
        print(f'{lang}: {total} texts in {len(contexts)} contexts, {missing} unfinished')
    unused = [s for s in list(singular) + list(plural) if s not in used]
    if unused:
        print(f'{len(unused)} table entries no longer used:\n  ' + '\n  '.join(map(repr, unused)))
    return status


if __name__ == '__main__':
    sys.exit(main())
