// Text and numbers as they go into an HTML page or an SVG figure: escaped, and printed with
// enough digits to be compared with summary.json.
#pragma once

#include <string>

namespace hpcontact::post {

/// `text` as HTML character data or attribute value: & < > " ' replaced by their entities, so
/// that a user's string (a body name, a file name, a message) is shown as written and never
/// read as markup.
std::string escape_html(const std::string& text);

/// A number with 10 significant digits (%.10g): a reader of the page gets it back to a relative
/// 5e-10; not finite: "nan", "inf" or "-inf".
std::string number_text(double value);

/// A number for an axis tick or a caption: %g (6 significant digits).
std::string short_number(double value);

}  // namespace hpcontact::post

namespace hpcontact::post {

/// A whole HTML document: `title` (escaped) in <title> and the page's style sheet inline; `body`
/// is HTML already. No script, no link to anything outside the page.
std::string html_document(const std::string& title, const std::string& body);

}  // namespace hpcontact::post
