#!/usr/bin/env python3
"""The Word reference documents of the relazione (issue 36, item 6).

usage: make_reference_docx.py [OUT_DIR]   (default: this script's folder)

Writes reference-it.docx and reference-en.docx, whose parts `assess run
--docx` copies into every Word relazione (styles, numbering, settings,
footer, theme, fonts and the section properties; embedded in the library at
build time, libassess/CMakeLists.txt; docx_writer.cpp writes the body) so
that the Word edition prints as the PDF does (html_writer.cpp's print style
sheet):
  - A4 (210 x 297 mm) with the PDF's margins: 16 mm top, 15 mm sides, 18 mm
    bottom;
  - page numbers at the bottom right, "pag. x di y" (English: "page x of y"),
    8 pt grey, as the PDF's footer;
  - DejaVu Sans, body 10.5 pt, table text 8.5 pt, captions 9.5 pt italic,
    headings 13.5 / 12 / 11 / 10.5 pt in near-black, kept with what follows;
  - tables with thin grey borders and a grey header row;
  - the verdict colours as character styles: "Verdetto OK" (green #11661F,
    bold), "Verdetto KO" (red #B3001B, bold), "Nota" (8 pt grey), which the
    writer puts on each verdict word, D/C and note (docx_writer.cpp).

It starts from pandoc's own default reference document (`pandoc
--print-default-data-file reference.docx`, pandoc 2.17 of Debian 12) and
edits its XML; commit both files. pandoc is needed only here, by whoever
regenerates them (not by the build nor by `assess`: issue 36, item 7).
"""
import io
import os
import re
import subprocess
import sys
import zipfile

MM = 1440 / 25.4  # twips per millimetre

FOOTER = """<?xml version="1.0" encoding="UTF-8" standalone="yes"?>
<w:ftr xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"
 xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships">
<w:p><w:pPr><w:jc w:val="right"/><w:spacing w:before="0" w:after="0"/></w:pPr>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:t xml:space="preserve">{page} </w:t></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:fldChar w:fldCharType="begin"/></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:instrText xml:space="preserve"> PAGE </w:instrText></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:fldChar w:fldCharType="separate"/></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:t>1</w:t></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:fldChar w:fldCharType="end"/></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:t xml:space="preserve"> {of} </w:t></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:fldChar w:fldCharType="begin"/></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:instrText xml:space="preserve"> NUMPAGES </w:instrText></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:fldChar w:fldCharType="separate"/></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:t>1</w:t></w:r>
<w:r><w:rPr><w:color w:val="555555"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr><w:fldChar w:fldCharType="end"/></w:r>
</w:p></w:ftr>
"""

SECTION = ('<w:sectPr><w:footerReference w:type="default" r:id="rIdAssessFooter"/>'
           '<w:pgSz w:w="11906" w:h="16838"/>'
           '<w:pgMar w:top="{top}" w:right="{side}" w:bottom="{bottom}" w:left="{side}" w:header="454" '
           'w:footer="454" w:gutter="0"/></w:sectPr>')

NEW_STYLES = """
  <w:style w:type="character" w:customStyle="1" w:styleId="VerdettoOK">
    <w:name w:val="Verdetto OK"/><w:basedOn w:val="DefaultParagraphFont"/>
    <w:rPr><w:b/><w:bCs/><w:color w:val="11661F"/></w:rPr>
  </w:style>
  <w:style w:type="character" w:customStyle="1" w:styleId="VerdettoKO">
    <w:name w:val="Verdetto KO"/><w:basedOn w:val="DefaultParagraphFont"/>
    <w:rPr><w:b/><w:bCs/><w:color w:val="B3001B"/></w:rPr>
  </w:style>
  <w:style w:type="character" w:customStyle="1" w:styleId="Nota">
    <w:name w:val="Nota"/><w:basedOn w:val="DefaultParagraphFont"/>
    <w:rPr><w:color w:val="444444"/><w:sz w:val="16"/><w:szCs w:val="16"/></w:rPr>
  </w:style>
"""

TABLE_STYLE = """<w:tblBorders>
        <w:top w:val="single" w:sz="4" w:space="0" w:color="BBBBBB"/>
        <w:left w:val="single" w:sz="4" w:space="0" w:color="BBBBBB"/>
        <w:bottom w:val="single" w:sz="4" w:space="0" w:color="BBBBBB"/>
        <w:right w:val="single" w:sz="4" w:space="0" w:color="BBBBBB"/>
        <w:insideH w:val="single" w:sz="4" w:space="0" w:color="BBBBBB"/>
        <w:insideV w:val="single" w:sz="4" w:space="0" w:color="BBBBBB"/>
      </w:tblBorders>
      <w:tblCellMar>"""


def style_block(styles, sid):
    m = re.search(r'<w:style [^>]*w:styleId="%s">.*?</w:style>' % sid, styles, re.S)
    if not m:
        sys.exit(f"pandoc's reference.docx has no style {sid}")
    return m


def set_run(styles, sid, props):
    """Replace (or add) the character properties of style `sid`."""
    m = style_block(styles, sid)
    block = m.group(0)
    if "<w:rPr>" in block:
        block = re.sub(r"<w:rPr>.*?</w:rPr>", "<w:rPr>" + props + "</w:rPr>", block, flags=re.S)
    else:
        block = block.replace("</w:style>", "<w:rPr>" + props + "</w:rPr></w:style>")
    return styles[:m.start()] + block + styles[m.end():]


def make(lang, default):
    it = lang == "it"
    files = {}
    with zipfile.ZipFile(io.BytesIO(default)) as z:
        for n in z.namelist():
            files[n] = z.read(n)
    doc = files["word/document.xml"].decode("utf-8")
    sect = SECTION.format(top=round(16 * MM), side=round(15 * MM), bottom=round(18 * MM))
    doc = re.sub(r"<w:sectPr\s*/>|<w:sectPr>.*?</w:sectPr>", sect, doc, flags=re.S)
    files["word/document.xml"] = doc.encode("utf-8")
    files["word/footer1.xml"] = FOOTER.format(page="pag." if it else "page", of="di" if it else "of").encode("utf-8")
    rels = files["word/_rels/document.xml.rels"].decode("utf-8")
    rels = rels.replace("</Relationships>", '<Relationship Type="http://schemas.openxmlformats.org/officeDocument/2006/'
                        'relationships/footer" Id="rIdAssessFooter" Target="footer1.xml" /></Relationships>')
    files["word/_rels/document.xml.rels"] = rels.encode("utf-8")
    ct = files["[Content_Types].xml"].decode("utf-8")
    ct = ct.replace("</Types>", '<Override PartName="/word/footer1.xml" ContentType="application/vnd.openxmlformats-'
                    'officedocument.wordprocessingml.footer+xml" /></Types>')
    files["[Content_Types].xml"] = ct.encode("utf-8")

    st = files["word/styles.xml"].decode("utf-8")
    font = '<w:rFonts w:ascii="DejaVu Sans" w:hAnsi="DejaVu Sans" w:eastAsia="DejaVu Sans" w:cs="DejaVu Sans" />'
    st = re.sub(r"<w:rFonts [^>]*/>", font, st, count=1)  # the document default
    st = re.sub(r'(<w:rPrDefault>.*?)<w:sz w:val="24" />\s*<w:szCs w:val="24" />', r'\1<w:sz w:val="21" /><w:szCs w:val="21" />',
                st, count=1, flags=re.S)
    st = re.sub(r'<w:lang w:val="en-US"', '<w:lang w:val="%s"' % ("it-IT" if it else "en-GB"), st, count=1)
    heading = {"Heading1": 27, "Heading2": 24, "Heading3": 22, "Heading4": 21, "Heading5": 21, "Heading6": 21}
    for sid, half_points in heading.items():
        st = set_run(st, sid, f'{font}<w:b /><w:bCs /><w:color w:val="111111" /><w:sz w:val="{half_points}" />'
                              f'<w:szCs w:val="{half_points}" />')
    st = set_run(st, "Title", f'{font}<w:b /><w:bCs /><w:color w:val="111111" /><w:sz w:val="34" /><w:szCs w:val="34" />')
    st = set_run(st, "Compact", '<w:sz w:val="17" /><w:szCs w:val="17" />')  # the tables' paragraphs: 8.5 pt
    for sid in ("Caption", "TableCaption", "ImageCaption"):
        st = set_run(st, sid, '<w:i /><w:iCs /><w:color w:val="111111" /><w:sz w:val="19" /><w:szCs w:val="19" />')
    st = set_run(st, "Hyperlink", '<w:color w:val="111111" />')
    st = st.replace("<w:tblCellMar>", TABLE_STYLE, 1)
    st = st.replace("</w:styles>", NEW_STYLES + "</w:styles>")
    files["word/styles.xml"] = st.encode("utf-8")

    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        for n in sorted(files, key=lambda n: (n != "[Content_Types].xml", n)):
            info = zipfile.ZipInfo(n, date_time=(2024, 1, 1, 0, 0, 0))  # reproducible bytes
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, files[n])
    return out.getvalue()


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    default = subprocess.run(["pandoc", "--print-default-data-file", "reference.docx"], check=True,
                             capture_output=True).stdout
    for lang in ("it", "en"):
        with open(os.path.join(out_dir, f"reference-{lang}.docx"), "wb") as f:
            f.write(make(lang, default))
    print(f"wrote reference-it.docx and reference-en.docx in {out_dir}")


if __name__ == "__main__":
    main()
