"""The help behind ParaView's "?" button, as the build generated it from the filters' XML.

Run as: pvbatch test_plugin_help.py HELP_DIR PLUGIN FILTERS_DIR
  HELP_DIR     where paraview_add_plugin writes the pages and the .qch (<plugin binary dir>/paraview_help)
  PLUGIN       the built plugin (FlowAlignedSurfaces.so), which carries the .qch
  FILTERS_DIR  the folder of the filters' XML (Plugin/Filters)

For each filter of the XML: its page exists, is titled with its label and name, shows its long
help and its documentation, and has one row per property, in the XML's order, with the
property's label and documentation.  The .qch (what the GUI's help window reads) holds every
page byte for byte, and the plugin carries that .qch.  Expected values come from the XML, not
from the pages: a filter, a property or a sentence lost on the way fails.
"""
import base64
import glob
import os
import re
import sqlite3
import sys
import xml.etree.ElementTree as ET
import zlib

help_dir, plugin, filters_dir = sys.argv[1:4]
errors = []
EXPECTED_FILTERS = {"FlowAlignedSurface", "FlowAlignedParametrize", "FlowTexture",
                    "GrowBoundary", "StreamSurfaceFromCurve"}
# The property elements ParaView's stylesheet (paraview_servermanager_convert_xml.xsl) documents.
PROPERTY_TAGS = ("DoubleVectorProperty", "InputProperty", "IntVectorProperty",
                 "StringVectorProperty", "ProxyProperty", "IdTypeVectorProperty")


def squeeze(text):
    """Whitespace as HTML shows it: the XML's line breaks and indentation are one space."""
    return " ".join((text or "").split())


def text_of(element):
    return squeeze("".join(element.itertext())) if element is not None else ""


def documentation(element):
    """(long_help, body) of an element's <Documentation>; the body is what the pages show."""
    doc = element.find("Documentation")
    if doc is None:
        return "", ""
    return squeeze(doc.get("long_help")), text_of(doc)


# The filters, from the XML.
filters = {}
for xml_file in sorted(glob.glob(os.path.join(filters_dir, "*.xml"))):
    for group in ET.parse(xml_file).getroot().findall("ProxyGroup"):
        if group.get("name") != "filters":
            continue
        for proxy in group.findall("SourceProxy"):
            name = proxy.get("name")
            properties = [(p.get("label") or p.get("name"), documentation(p)[1])
                          for p in proxy if p.tag in PROPERTY_TAGS]
            filters[name] = (proxy.get("label") or name, documentation(proxy), properties,
                             os.path.basename(xml_file))
if set(filters) != EXPECTED_FILTERS:
    errors.append("the XML of %s declares the filters %s, expected %s"
                  % (filters_dir, sorted(filters), sorted(EXPECTED_FILTERS)))

# Each filter's page.
pages = {}
for name, (label, (long_help, body), properties, xml_file) in sorted(filters.items()):
    page_file = os.path.join(help_dir, "filters.%s.html" % name)
    if not os.path.isfile(page_file):
        errors.append("%s (%s): no help page %s" % (name, xml_file, page_file))
        continue
    with open(page_file, "rb") as f:
        pages[name] = f.read()
    page = ET.fromstring(pages[name])
    where = "%s (%s)" % (os.path.basename(page_file), xml_file)
    title = text_of(page.find("body/h2"))
    if title != "%s (%s)" % (label, name):
        errors.append("%s: the title is %r, expected %r" % (where, title, "%s (%s)" % (label, name)))
    if not long_help:
        errors.append("%s: the filter has no long_help in its XML" % where)
    shown_long_help = text_of(page.find("body/i/p"))
    if shown_long_help != long_help:
        errors.append("%s: the long help shown is %r, the XML's is %r" % (where, shown_long_help, long_help))
    description = text_of(page.find("body/div[@class='description']"))
    if not body or description != body:
        errors.append("%s: the description shown is %r, the XML's documentation is %r"
                      % (where, description, body))
    rows = [(text_of(row.find("th")), text_of(row.find("td")))
            for row in page.findall("body/table/tr") if row.find("td") is not None]
    shown_labels = [label for label, _ in rows]
    expected_labels = [label for label, _ in properties]
    if shown_labels != expected_labels:
        errors.append("%s: the properties shown are %s, the XML's are %s"
                      % (where, shown_labels, expected_labels))
    for (prop_label, prop_doc), (_, shown_doc) in zip(properties, rows):
        if not prop_doc:
            errors.append("%s: property %s has no documentation in the XML" % (where, prop_label))
        elif shown_doc != prop_doc:
            errors.append("%s: property %s shows %r, the XML says %r" % (where, prop_label, shown_doc, prop_doc))

# The .qch: the help window's source.  Qt stores each file zlib-compressed behind its length (a
# 4-byte big-endian integer, qCompress's format).
qch_file = os.path.join(help_dir, "FlowAlignedSurfaces.qch")
if not os.path.isfile(qch_file):
    errors.append("no %s" % qch_file)
else:
    qch = sqlite3.connect("file:%s?mode=ro" % qch_file, uri=True)
    namespaces = [row[0] for row in qch.execute("SELECT Name FROM NamespaceTable")]
    if namespaces != ["FlowAlignedSurfaces.org"]:
        errors.append("%s: namespaces %s, expected FlowAlignedSurfaces.org" % (qch_file, namespaces))
    stored = {}
    for file_name, data in qch.execute(
            "SELECT n.Name, d.Data FROM FileNameTable n JOIN FileDataTable d ON n.FileId = d.Id"):
        if data:  # qhelpgenerator's first row is an empty placeholder
            stored[file_name] = zlib.decompress(bytes(data)[4:])
    for name, page in sorted(pages.items()):
        file_name = "filters.%s.html" % name
        if file_name not in stored:
            errors.append("%s does not hold %s (it holds %s)" % (qch_file, file_name, sorted(stored)))
        elif stored[file_name] != page:
            errors.append("%s holds a %s that differs from the page in %s" % (qch_file, file_name, help_dir))
    qch.close()

    # The plugin carries the .qch as base64 text in a few string literals (ParaView's
    # ProcessXML -base64): every long base64 run of the library is a piece of the .qch's base64,
    # and together they are all of it.
    with open(qch_file, "rb") as f:
        qch_base64 = base64.b64encode(f.read())
    with open(plugin, "rb") as f:
        runs = [run for run in re.findall(rb"[A-Za-z0-9+/=]{256,}", f.read()) if run in qch_base64]
    if sum(len(run) for run in runs) != len(qch_base64):
        errors.append("%s does not carry %s: %d of its %d base64 characters found"
                      % (plugin, qch_file, sum(len(run) for run in runs), len(qch_base64)))

if errors:
    raise RuntimeError("test_plugin_help: FAILED\n  " + "\n  ".join(errors))
print("test_plugin_help: %d filters, %d properties: every page names its filter's properties and "
      "shows the XML's documentation; the .qch and the plugin carry them"
      % (len(filters), sum(len(p) for _, _, p, _ in filters.values())))
