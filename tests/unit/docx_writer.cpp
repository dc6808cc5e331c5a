// The Word writer's own XML (issue 36, items 6 and 7): a small Document with
// every block type written to a .docx, the package read back with libzip and
// its parts checked: the reference document's styles, page and footer; the
// headings' styles, numbers and bookmarks; links within the document as
// hyperlinks to those bookmarks, links into the other document as text; the
// verdict colours; the bulleted list; the table's repeated header row, right
// aligned figures, notes and caption; the contents as Word's TOC field,
// updated on opening; each figure a picture with the SVG in Word 2016's
// extension and a PNG drawn from it (decoded here with zlib: its size, and
// black where the SVG is black); a figure that cannot be drawn is an
// InputError naming --docx. (The relazione's Word files are read back with
// python-docx in cli.report_files_*.)
#include <doctest/doctest.h>

#include "report/zip_archive.hpp"
#include "tag_balance.hpp"

#include "assess/report/docx_writer.hpp"
#include "assess/support/error.hpp"

#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace assess;

// 200 x 100 user units, the left half black: a 2:1 picture.
const char* kSvg =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 200 100\">"
    "<rect x=\"0\" y=\"0\" width=\"200\" height=\"100\" fill=\"#ffffff\"/>"
    "<rect x=\"0\" y=\"0\" width=\"100\" height=\"100\" fill=\"#000000\"/></svg>\n";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size())) ++n;
  return n;
}

std::uint32_t be32(const std::string& s, std::size_t at) {
  return std::uint32_t((unsigned char)s[at]) << 24 | std::uint32_t((unsigned char)s[at + 1]) << 16 |
         std::uint32_t((unsigned char)s[at + 2]) << 8 | std::uint32_t((unsigned char)s[at + 3]);
}

// A PNG of 8-bit RGB rows with filter 0 (what the writer makes), decoded.
struct Png {
  std::uint32_t width = 0, height = 0;
  std::string pixels;  // RGB rows
  bool ok = false;
  unsigned char at(std::uint32_t x, std::uint32_t y, int channel) const {
    return (unsigned char)pixels[std::size_t(y) * (1 + 3 * std::size_t(width)) + 1 + 3 * std::size_t(x) + channel];
  }
};

Png decode(const std::string& png) {
  Png p;
  if (png.compare(0, 8, std::string("\x89PNG\r\n\x1a\n", 8)) != 0) return p;
  std::string idat;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t n = be32(png, at);
    const std::string type = png.substr(at + 4, 4);
    const std::string data = png.substr(at + 8, n);
    const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(png.data() + at + 4), uInt(n + 4));
    if (crc != be32(png, at + 8 + n)) return p;  // every chunk's CRC
    if (type == "IHDR") {
      p.width = be32(data, 0);
      p.height = be32(data, 4);
      if (data.substr(8, 5) != std::string("\x08\x02\x00\x00\x00", 5)) return p;
    } else if (type == "IDAT") {
      idat += data;
    } else if (type == "IEND") {
      uLongf size = uLongf(p.height) * (1 + 3 * uLongf(p.width));
      p.pixels.assign(size, '\0');
      p.ok = uncompress(reinterpret_cast<Bytef*>(p.pixels.data()), &size, reinterpret_cast<const Bytef*>(idat.data()),
                        uLong(idat.size())) == Z_OK &&
             size == p.pixels.size();
      return p;
    }
    at += 12 + n;
  }
  return p;
}

Span link_to(const std::string& text, const std::string& anchor, const std::string& doc = "") {
  Span s(text);
  s.link = anchor;
  s.doc = doc;
  return s;
}

Document sample() {
  DocumentBuilder b("Relazione di prova <1> & \"2\"", "it");
  b.set_subtitle("Sottotitolo");
  b.add_contents("Sommario", 3);
  b.add_heading("Premessa", 2, true, true, "sec-premessa");
  b.add_paragraph(Inline{Span("Esito: "), Span("VERIFICATO", true, Tone::ok), Span(", "),
                         Span("D/C = 1,20", true, Tone::fail), Span(" vedi "), link_to("§2", "sec-verifiche"),
                         Span(" e "), link_to("i tabulati", "T-sec", "tabulati"), Span(" e la "),
                         link_to("figura", "fig-prova")});
  b.add_paragraph("Una nota.", "note");
  b.add_paragraph("Didascalia libera.", "caption");
  b.add_list({Inline{Span("primo")}, Inline{Span("secondo", false, Tone::fail)}});
  b.add_heading("Verifiche", 2, true, true, "sec-verifiche");
  b.add_heading("Non numerata", 3, false, false, "sec-libera");
  Cell dc = numeric_cell("0,85", "Circ. C8.7.1.2.1");
  dc.tone = Tone::ok;
  dc.strong = true;
  Cell gov("M1");
  gov.highlight = true;
  b.add_cell_table({Cell("Meccanismo"), numeric_cell("D/C")}, {{gov, dc}, {Cell("M2"), numeric_cell("1,10")}},
                   "Tabella 1: verifiche");
  b.add_svg(kSvg, "Figura di prova.", "fig-prova");
  b.add_svg_grid({{kSvg, "a"}, {kSvg, "b"}, {kSvg, "c"}, {kSvg, "d"}}, "Quattro pannelli.", "fig-griglia");
  b.add_pre("riga 1\n\triga 2");
  Box box;
  box.style = "conclusion";
  box.tone = Tone::fail;
  DocumentBuilder inner("x", "it");
  inner.add_paragraph("Dentro il riquadro.");
  box.content = inner.take_blocks();
  b.add_box(std::move(box));
  b.add_signature({"Norcia, 1 gennaio 2026", "Il tecnico"});
  b.add_raw_html("<p>Testo <b>grez</b>zo &amp; altro</p><p>e &amp;lt;fine&gt;</p>");
  return b.document();
}

std::map<std::string, std::string> parts_of(const std::string& bytes) {
  std::map<std::string, std::string> parts;
  for (auto& e : detail::read_zip(bytes, "test")) parts[e.name] = std::move(e.data);
  return parts;
}

}  // namespace

TEST_CASE("the Word writer's parts: every block type of the document model") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "assess_unit_docx";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "prova.docx").string();
  write_docx(sample(), path);
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.compare(0, 2, "PK") == 0);
  auto parts = parts_of(bytes);
  for (const char* name : {"[Content_Types].xml", "_rels/.rels", "word/document.xml", "word/_rels/document.xml.rels",
                           "word/styles.xml", "word/numbering.xml", "word/settings.xml", "word/footer1.xml",
                           "word/theme/theme1.xml", "word/fontTable.xml", "docProps/core.xml"})
    CHECK_MESSAGE(parts.count(name), name);
  const std::string& doc = parts["word/document.xml"];
  for (const auto& part : parts) {  // (no structured binding: clang 14 cannot capture one in CHECK_MESSAGE)
    const std::string& name = part.first;
    if (name.size() > 4 && (name.compare(name.size() - 4, 4, ".xml") == 0 || name.compare(name.size() - 5, 5, ".rels") == 0))
      CHECK_MESSAGE(tag_balance(part.second) == "", name);
  }

  SUBCASE("the reference document's page, styles and footer") {
    // A4 with the PDF's margins (16/15/18/15 mm, in twips) and the footer "pag. PAGE di NUMPAGES".
    CHECK(count(doc, "<w:pgSz w:w=\"11906\" w:h=\"16838\"/>") == 1);
    CHECK(count(doc, "w:top=\"907\" w:right=\"850\" w:bottom=\"1020\" w:left=\"850\"") == 1);
    CHECK(count(doc, "<w:footerReference w:type=\"default\" r:id=\"rIdAssessFooter\"/>") == 1);
    CHECK(count(parts["word/_rels/document.xml.rels"], "Id=\"rIdAssessFooter\"") == 1);
    CHECK(count(parts["word/footer1.xml"], "pag. ") == 1);
    CHECK(count(parts["word/footer1.xml"], " NUMPAGES ") == 1);
    for (const char* style : {"w:styleId=\"VerdettoOK\"", "w:styleId=\"VerdettoKO\"", "w:styleId=\"Nota\"",
                              "w:styleId=\"TableCaption\"", "w:styleId=\"ImageCaption\"", "w:styleId=\"Heading1\""})
      CHECK_MESSAGE(count(parts["word/styles.xml"], style) == 1, style);
    CHECK(count(parts["docProps/core.xml"], "<dc:title>Relazione di prova &lt;1&gt; &amp; &quot;2&quot;</dc:title>") == 1);
  }
  SUBCASE("title, headings with their numbers and bookmarks") {
    CHECK(count(doc, "<w:pStyle w:val=\"Title\"/></w:pPr><w:r><w:t xml:space=\"preserve\">Relazione di prova &lt;1&gt; "
                     "&amp; &quot;2&quot;</w:t>") == 1);
    CHECK(count(doc, "<w:pStyle w:val=\"Subtitle\"/>") == 1);
    // Level 2 -> Word's Heading 1, a new page from the second section on; level 3 -> Heading 2; an
    // unnumbered heading outside the contents.
    CHECK(count(doc, "<w:pStyle w:val=\"Heading1\"/></w:pPr><w:bookmarkStart w:id=\"0\" "
                     "w:name=\"sec-premessa\"/><w:r><w:t xml:space=\"preserve\">1 Premessa</w:t></w:r><w:bookmarkEnd w:id=\"0\"/>") == 1);
    CHECK(count(doc, "<w:pStyle w:val=\"Heading1\"/><w:pageBreakBefore/></w:pPr><w:bookmarkStart w:id=\"1\" "
                     "w:name=\"sec-verifiche\"/><w:r><w:t xml:space=\"preserve\">2 Verifiche</w:t>") == 1);
    CHECK(count(doc, "<w:pStyle w:val=\"Heading2\"/><w:outlineLvl w:val=\"9\"/></w:pPr><w:bookmarkStart w:id=\"2\" "
                     "w:name=\"sec-libera\"/><w:r><w:t xml:space=\"preserve\">Non numerata</w:t>") == 1);
    // Bookmark ids unique.
    std::set<std::string> ids;
    static const std::regex start(R"re(<w:bookmarkStart w:id="(\d+)")re");
    for (auto it = std::sregex_iterator(doc.begin(), doc.end(), start); it != std::sregex_iterator(); ++it)
      CHECK(ids.insert((*it)[1]).second);
    CHECK(ids.size() == 5);  // three headings, two figures
  }
  SUBCASE("spans: verdict colours, bold, links within the document and into the other") {
    CHECK(count(doc, "<w:r><w:rPr><w:rStyle w:val=\"VerdettoOK\"/><w:b/><w:bCs/></w:rPr><w:t xml:space=\"preserve\">"
                     "VERIFICATO</w:t></w:r>") == 1);
    CHECK(count(doc, "<w:rStyle w:val=\"VerdettoKO\"/><w:b/><w:bCs/></w:rPr><w:t xml:space=\"preserve\">D/C = 1,20</w:t>") == 1);
    CHECK(count(doc, "<w:hyperlink w:anchor=\"sec-verifiche\" w:history=\"1\"><w:r><w:rPr><w:rStyle w:val=\"Hyperlink\"/>"
                     "</w:rPr><w:t xml:space=\"preserve\">§2</w:t></w:r></w:hyperlink>") == 1);
    CHECK(count(doc, "<w:hyperlink w:anchor=\"fig-prova\"") == 1);
    CHECK(count(doc, "T-sec") == 0);  // the tabulati's anchor is not in this document: text
    CHECK(count(doc, "<w:r><w:t xml:space=\"preserve\">i tabulati</w:t></w:r>") == 1);
    // Every hyperlink's anchor is a bookmark of the document.
    static const std::regex anchor(R"re(<w:hyperlink w:anchor="([^"]+)")re");
    for (auto it = std::sregex_iterator(doc.begin(), doc.end(), anchor); it != std::sregex_iterator(); ++it)
      CHECK_MESSAGE(count(doc, "w:name=\"" + (*it)[1].str() + "\"/>") == 1,
                    (*it)[1].str());
  }
  SUBCASE("paragraph styles, the list, preformatted text, signature, raw HTML, a box's content") {
    CHECK(count(doc, "<w:rStyle w:val=\"Nota\"/></w:rPr><w:t xml:space=\"preserve\">Una nota.</w:t>") == 1);
    CHECK(count(doc, "<w:pStyle w:val=\"Caption\"/></w:pPr><w:r><w:t xml:space=\"preserve\">Didascalia libera.") == 1);
    CHECK(count(doc, "<w:numPr><w:ilvl w:val=\"0\"/><w:numId w:val=\"1001\"/></w:numPr>") == 2);
    const std::string& numbering = parts["word/numbering.xml"];
    CHECK(count(numbering, "<w:num w:numId=\"1001\"><w:abstractNumId w:val=\"991\"/></w:num>") == 1);
    CHECK(count(numbering, "<w:lvlText w:val=\"\xE2\x80\xA2\"/>") >= 1);
    CHECK(numbering.find("w:abstractNumId=\"991\"") < numbering.find("<w:num "));  // abstract definitions first
    CHECK(count(doc, "<w:rStyle w:val=\"VerbatimChar\"/></w:rPr><w:t xml:space=\"preserve\">riga 1</w:t><w:br/><w:tab/>"
                     "<w:t xml:space=\"preserve\">riga 2</w:t>") == 1);
    CHECK(count(doc, ">Il tecnico</w:t>") == 1);
    CHECK(count(doc, ">Testo grezzo &amp; altro e &amp;lt;fine&gt;</w:t>") == 1);  // inline tags join, blocks part
    CHECK(count(doc, ">Dentro il riquadro.</w:t>") == 1);
  }
  SUBCASE("the table: caption, repeated header row, right-aligned figures, notes, the governing row") {
    const auto caption = doc.find("<w:pStyle w:val=\"TableCaption\"/></w:pPr><w:r><w:t xml:space=\"preserve\">Tabella 1: verifiche");
    REQUIRE(caption != std::string::npos);
    CHECK(doc.find("<w:tbl>", caption) != std::string::npos);
    CHECK(count(doc, "<w:tbl>") == 1);
    CHECK(count(doc, "<w:tblHeader/>") == 1);
    // Column widths as a browser's automatic layout: each column's longest line, "Meccanismo" (10 characters
    // of 0.56 em at 8.5 pt: 952 twips) and the note "Circ. C8.7.1.2.1" (16 at 8 pt: 1433.6 twips), each with
    // 216 twips of margins, widened in proportion to the text width, 10206 twips: 4231 and 5975.
    CHECK(count(doc, "<w:tblGrid><w:gridCol w:w=\"4231\"/><w:gridCol w:w=\"5975\"/></w:tblGrid>") == 1);
    CHECK(count(doc, "<w:tcW w:w=\"5975\" w:type=\"dxa\"/>") == 3);
    CHECK(count(doc, "<w:jc w:val=\"right\"/>") == 3);  // "D/C", "0,85", "1,10"
    CHECK(count(doc, "<w:br/></w:r><w:r><w:rPr><w:rStyle w:val=\"Nota\"/></w:rPr><w:t xml:space=\"preserve\">Circ. C8.7.1.2.1") == 1);
    CHECK(count(doc, "w:fill=\"FFF6D6\"") == 1);
    CHECK(count(doc, "<w:rStyle w:val=\"VerdettoOK\"/><w:b/><w:bCs/></w:rPr><w:t xml:space=\"preserve\">0,85") == 1);
  }
  SUBCASE("the contents: Word's TOC field, updated on opening") {
    // Contents of depth 3: levels 2 and 3, Word's Heading 1 and 2.
    CHECK(count(doc, "<w:docPartGallery w:val=\"Table of Contents\"/>") == 1);
    CHECK(count(doc, "<w:fldChar w:fldCharType=\"begin\" w:dirty=\"true\"/></w:r><w:r><w:instrText xml:space=\"preserve\"> "
                     "TOC \\o \"1-2\" \\h \\z \\u </w:instrText>") == 1);
    CHECK(count(doc, "<w:fldChar w:fldCharType=\"separate\"/>") == 1);
    CHECK(count(doc, "<w:fldChar w:fldCharType=\"end\"/>") == 1);
    CHECK(count(doc, "<w:pStyle w:val=\"TOCHeading\"/></w:pPr><w:r><w:t xml:space=\"preserve\">Sommario") == 1);
    CHECK(count(doc, "<w:hyperlink w:anchor=\"sec-premessa\" w:history=\"1\"><w:r><w:rPr><w:rStyle w:val=\"Hyperlink\"/>"
                     "</w:rPr><w:t xml:space=\"preserve\">1 Premessa</w:t>") == 1);
    CHECK(count(doc, "Non numerata") == 1);  // not listed
    CHECK(count(parts["word/settings.xml"], "<w:updateFields w:val=\"true\"/>") == 1);
  }
  SUBCASE("figures: the SVG in Word 2016's extension, a PNG drawn from it, the size of the PDF's") {
    // One figure and four panels: five pictures, each an SVG and a PNG part and relationship.
    CHECK(count(doc, "<pic:pic>") == 5);
    CHECK(count(doc, "<a:ext uri=\"{96DAC541-7B7A-43D3-8B79-37D633B846F1}\"><asvg:svgBlip "
                     "xmlns:asvg=\"http://schemas.microsoft.com/office/drawing/2016/SVG/main\" r:embed=\"rIdSvg") == 5);
    const std::string& rels = parts["word/_rels/document.xml.rels"];
    const std::string& types = parts["[Content_Types].xml"];
    CHECK(count(types, "<Default Extension=\"png\" ContentType=\"image/png\"/>") == 1);
    CHECK(count(types, "<Default Extension=\"svg\" ContentType=\"image/svg+xml\"/>") == 1);
    for (int k = 1; k <= 5; ++k) {
      const std::string n = std::to_string(k);
      CHECK(count(doc, "<a:blip r:embed=\"rIdPng" + n + "\">") == 1);
      CHECK(count(rels, "Id=\"rIdPng" + n + "\" Type=\"http://schemas.openxmlformats.org/officeDocument/2006/relationships/image\" "
                        "Target=\"media/figure" + n + ".png\"") == 1);
      CHECK(count(rels, "Target=\"media/figure" + n + ".svg\"") == 1);
      CHECK(parts["word/media/figure" + n + ".svg"].compare(0, 4, "<svg") == 0);  // the prolog dropped
      CHECK(count(doc, "<wp:docPr id=\"" + n + "\"") == 1);
    }
    // The full-width figure: 170 mm (the PDF's widest) by 85 mm (the viewBox's 1:2), in EMU (36000 a mm).
    CHECK(count(doc, "<wp:extent cx=\"6120000\" cy=\"3060000\"/>") == 1);
    // Its PNG at 120 pixels an inch: 170 mm -> 803 px, 85 mm -> 402 px; black on the left, white on the right.
    const Png png = decode(parts["word/media/figure1.png"]);
    REQUIRE(png.ok);
    CHECK(png.width == 803);
    CHECK(png.height == 402);
    for (int c = 0; c < 3; ++c) {
      CHECK(int(png.at(100, 200, c)) == 0);
      CHECK(int(png.at(700, 200, c)) == 255);
    }
    // The grid: panels a third of the text width less the gaps ((180 - 6) / 3 = 58 mm: 2088000 EMU), three a row
    // on centre tab stops, each label below its panel, then the one caption.
    // (the reference's text width: 11906 - 2 x 850 twips = 10206 twips = 180.02 mm).
    const double panel_mm = (10206 * 25.4 / 1440 - 6) / 3;
    CHECK(count(doc, "<wp:extent cx=\"" + std::to_string(std::lround(panel_mm * 36000)) + "\" cy=\"" +
                         std::to_string(std::lround(panel_mm / 2 * 36000)) + "\"/>") == 4);
    CHECK(count(doc, "<w:tab w:val=\"center\" w:pos=\"1701\"/><w:tab w:val=\"center\" w:pos=\"5103\"/>"
                     "<w:tab w:val=\"center\" w:pos=\"8505\"/>") == 4);  // two rows: pictures and labels
    CHECK(count(doc, "<w:r><w:tab/></w:r><w:r><w:t xml:space=\"preserve\">d</w:t></w:r></w:p>") == 1);
    CHECK(count(doc, "<w:pStyle w:val=\"ImageCaption\"/></w:pPr><w:r><w:t xml:space=\"preserve\">Quattro pannelli.") == 1);
    CHECK(count(doc, "<w:pStyle w:val=\"ImageCaption\"/></w:pPr><w:r><w:t xml:space=\"preserve\">Figura di prova.") == 1);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("a figure the writer cannot draw is an InputError naming --docx and librsvg") {
  DocumentBuilder b("Prova", "en");
  b.add_heading("One", 2);
  b.add_svg("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\"><rect></svg>", "Broken.", "fig-broken");
  try {
    (void)docx_bytes(b.document(), "--docx r.docx");
    FAIL("no error");
  } catch (const InputError& e) {
    const std::string m = e.what();
    CHECK(m.find("--docx r.docx: librsvg cannot read a figure's SVG") == 0);
  }
}

TEST_CASE("the same document gives the same bytes") {
  const Document d = sample();
  CHECK(docx_bytes(d) == docx_bytes(d));
}
