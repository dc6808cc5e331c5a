// html_report.hpp: a document (document.hpp) written as one printable HTML
// page (html_writer.hpp): the builder of the campaign and fragility pages.
// The relazioni build their Document with DocumentBuilder and render it with
// every writer.
#pragma once

#include "assess/report/document.hpp"
#include "assess/report/html_writer.hpp"

#include <string>

namespace assess {

class HtmlReport : public DocumentBuilder {
 public:
  explicit HtmlReport(std::string title, std::string lang = "en") : DocumentBuilder(std::move(title), std::move(lang)) {}
  /// The complete HTML5 document.
  std::string str() const { return to_html(document()); }
};

}  // namespace assess
