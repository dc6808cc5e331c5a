// document.hpp: a report as a document model (issue 28, item 12): sections,
// paragraphs, tables, figures, boxes and notes in the chosen language, built
// once by the relazione's sections and rendered by thin writers (HTML and
// PDF through it: html_writer.hpp; Word: docx_writer.hpp; plain text at 120
// columns: text_writer.hpp). No writer computes or re-colours a verdict: a
// verdict is a Tone carried by the cell, span or box that shows it.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace assess {

/// How a piece of text reads as a verdict: plain, satisfied (green) or failing (red).
enum class Tone { plain, ok, fail };

/// The place in the text of a reference where the writer puts the section
/// number of its target (resolve_references, relazione.hpp): "§{§}" -> "§T3.2".
inline constexpr const char* section_number_mark = "{§}";

/// A run of inline text. `link` is an anchor ("sec-3", "M3", a figure id) of
/// the document `doc` ("": this one; else another document of the same
/// relazione by its key, Document::key: the body and its tabulati di calcolo
/// refer to each other, issue 36); every link is checked to resolve.
struct Span {
  std::string text;
  bool strong = false;
  Tone tone = Tone::plain;
  std::string link;
  bool user = false;  ///< the engineer's own words (project, names, descriptions): any language, printed as written
  std::string doc;    ///< the document `link` points into ("" this one)
  Span(std::string t = "", bool strong_ = false, Tone tone_ = Tone::plain, std::string link_ = "", bool user_ = false)
      : text(std::move(t)), strong(strong_), tone(tone_), link(std::move(link_)), user(user_) {}
};

/// A reference to a section: `text` holds section_number_mark where the
/// target's number goes ("tabulati di calcolo, §{§}"), `anchor` the target's
/// anchor, `doc` its document ("" this one).
inline Span reference(std::string text, std::string anchor, std::string doc = "") {
  Span s(std::move(text), false, Tone::plain, std::move(anchor));
  s.doc = std::move(doc);
  return s;
}
using Inline = std::vector<Span>;

/// A table cell: text, an optional second line in small type (formula,
/// clause, reason), right-aligned figures, a verdict tone (`strong`: the
/// D/C itself, bold), a highlighted row member (the governing one).
struct Cell {
  std::string text;
  std::string note;
  bool numeric = false;
  Tone tone = Tone::plain;
  bool strong = false;
  bool highlight = false;
  std::string link;        ///< an anchor the text links to ("M3"), or ""; section_number_mark in the text: its number
  std::string doc;         ///< the document of `link` ("" this one; Span::doc)
  bool user = false;       ///< the engineer's own words (Span::user)
  Cell() = default;
  Cell(std::string t) : text(std::move(t)) {}
  Cell(const char* t) : text(t) {}
  Cell(std::string t, std::string n) : text(std::move(t)), note(std::move(n)) {}
};

/// A right-aligned cell of figures: a number, or the heading of a column of numbers.
inline Cell numeric_cell(std::string text, std::string note = "") {
  Cell c(std::move(text), std::move(note));
  c.numeric = true;
  return c;
}

struct Heading {
  int level = 2;           ///< 2 section, 3 subsection, 4, 5 (1 is the title)
  std::string text;
  std::string anchor;      ///< unique id ("sec-4"); the writers number sections and link the contents to it
  bool new_page = false;   ///< a printed page break before it
  bool numbered = true;    ///< counted in the section numbering and listed in the contents
};

struct Paragraph {
  Inline text;
  std::string style;       ///< "" body, "meta" (smaller, grey), "note" (small), "caption"
  std::string lang;        ///< language of the text when it is not the document's ("en" warnings)
};

struct List {
  std::vector<Inline> items;
  std::string style;       ///< "" or "legend", "normativa"
};

struct Table {
  std::vector<Cell> header;
  std::vector<std::vector<Cell>> rows;
  std::string caption;
  std::string style;       ///< "" or "checks" (the checks tables: a hook for tests and CSS)
};

/// One picture: an SVG document and, in a grid, its label.
struct Panel {
  std::string svg;
  std::string label;
};

struct Figure {
  std::string id;          ///< unique, [A-Za-z][A-Za-z0-9_-]*
  std::string caption;
  std::vector<Panel> panels;
  bool grid = false;       ///< small multiples (three a row)
};

struct DocBlock;

/// A framed group of blocks: a verdict box, the conclusion, the probabilistic result.
struct Box {
  std::string style;       ///< "conclusion", "verdicts", "verdict", "method", "probabilistic", "note"
  Tone tone = Tone::plain;
  std::vector<std::pair<std::string, std::string>> data;  ///< data-* attributes of the HTML (test hooks)
  std::vector<DocBlock> content;
};

struct Preformatted {
  std::string text;
};

/// The place, date and signature lines.
struct Signature {
  std::vector<std::string> lines;
};

/// The table of contents (sommario): the writers list the numbered headings up to `depth`.
struct Contents {
  std::string title;
  int depth = 3;
};

/// HTML built by a caller that has no other writer (campaign and fragility
/// pages); the relazione never uses it. Other writers skip it.
struct RawHtml {
  std::string html;
};

struct DocBlock {
  std::variant<Heading, Paragraph, List, Table, Figure, Box, Preformatted, Signature, Contents, RawHtml> value;
  template <class T>
  DocBlock(T v) : value(std::move(v)) {}
};

struct Document {
  std::string title;
  std::string subtitle;
  std::string lang = "en";  ///< "it" | "en"
  /// Which document of a relazione this is ("" alone; "relazione", "tabulati"):
  /// the key other documents' references name (Span::doc).
  std::string key;
  /// Put before the number of every section ("T": the tabulati's "T3.2"), so
  /// that a section number names one place in either document.
  std::string number_prefix;
  std::vector<DocBlock> blocks;
};

/// Builds a Document (the API the report sections use). Figure ids are checked
/// (valid, unique); a nested report (a building's mechanism) sets an id prefix
/// and shifts its headings one or more levels down.
class DocumentBuilder {
 public:
  explicit DocumentBuilder(std::string title, std::string lang = "en");

  /// A heading; level 2 opens a section (a new printed page unless new_page is
  /// false), 3-5 subsections. `anchor` (with the id prefix before it) names
  /// it for references; "" gives one. Returns its anchor. InputError outside 2..5.
  std::string add_heading(const std::string& text, int level = 2, bool new_page = true, bool numbered = true,
                          const std::string& anchor = "");
  void add_paragraph(const std::string& text, const std::string& style = "");
  void add_paragraph(Inline text, const std::string& style = "", const std::string& lang = "");
  void add_list(std::vector<Inline> items, const std::string& style = "");
  /// A table of plain cells; rows must have the header's width (InputError).
  void add_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                 const std::string& caption = "");
  void add_cell_table(const std::vector<Cell>& header, const std::vector<std::vector<Cell>>& rows,
                      const std::string& caption, const std::string& style = "");
  /// A figure holding an SVG document (its XML prolog is dropped by the writers).
  void add_svg(const std::string& svg, const std::string& caption, const std::string& id);
  /// Small multiples, each with a short label.
  void add_svg_grid(const std::vector<std::pair<std::string, std::string>>& svgs_and_labels,
                    const std::string& caption, const std::string& id);
  void add_pre(const std::string& text);
  void add_box(Box box);
  void add_signature(std::vector<std::string> lines);
  void add_contents(const std::string& title, int depth = 3);
  void add_raw_html(const std::string& html);
  void add_block(DocBlock b);

  void set_subtitle(const std::string& text) { doc_.subtitle = text; }
  void set_key(const std::string& key) { doc_.key = key; }
  void set_number_prefix(const std::string& prefix) { doc_.number_prefix = prefix; }
  void set_lang(const std::string& lang) { doc_.lang = lang; }
  /// A prefix put before every figure id and anchor from now on ("M3-": a building's mechanism).
  void set_id_prefix(const std::string& prefix) { id_prefix_ = prefix; }
  /// Headings added from now on go `shift` levels deeper.
  void set_heading_shift(int shift) { heading_shift_ = shift; }
  const std::string& id_prefix() const { return id_prefix_; }
  int heading_shift() const { return heading_shift_; }
  std::size_t figure_count() const { return figure_ids_.size(); }

  const Document& document() const { return doc_; }
  /// The blocks built so far, moved out (a box's content built apart).
  std::vector<DocBlock> take_blocks();

 private:
  void check_figure_id(const std::string& id);
  Document doc_;
  std::vector<std::string> figure_ids_;
  bool has_section_ = false;
  std::string id_prefix_;
  int heading_shift_ = 0;
  int anchors_ = 0;
};

/// Plain text of an inline run.
std::string plain_text(const Inline& text);

/// The section number of every heading of `d`, in order ("3", "3.2"; "" for an
/// unnumbered one; with Document::number_prefix "T3.2"): one numbering for
/// every writer and for the contents.
std::vector<std::string> heading_numbers(const Document& d);

/// Resolves the references of documents that refer to each other (a
/// relazione and its tabulati di calcolo, issue 36): every Span and Cell with
/// a `link` must name an anchor (a heading's or a figure's id) of its
/// document (`doc`: "" the one it is in, else the document of that key);
/// section_number_mark in its text is replaced by the target heading's number
/// ("§{§}" -> "§T3.2"). @throws std::logic_error naming the reference when
/// a link does not resolve or a number is asked of a figure or an unnumbered
/// heading (a defect of the relazione's code, never of the input).
void resolve_references(const std::vector<Document*>& docs);

/// A line of the contents: a numbered heading and its section number.
struct ContentsEntry {
  const Heading* heading;
  std::string number;
};
/// The contents of `d`: its numbered headings down to level `depth`, in order
/// (every writer lists the same).
std::vector<ContentsEntry> contents_entries(const Document& d, int depth);

}  // namespace assess
