// Escaping and number printing for the HTML report.
#include "hpcontact/post/html_text.hpp"

#include <cmath>
#include <cstdio>

namespace hpcontact::post {

std::string escape_html(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

std::string printed(const char* format, double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, format, value + 0.0);  // + 0.0: no -0
  return buffer;
}

}  // namespace

std::string number_text(double value) { return printed("%.10g", value); }

std::string short_number(double value) { return printed("%g", value); }

}  // namespace hpcontact::post

namespace hpcontact::post {

std::string html_document(const std::string& title, const std::string& body) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         escape_html(title) +
         "</title>\n<style>\n"
         "body{font-family:sans-serif;margin:1.5em auto;max-width:1100px;color:#222;padding:0 1em}\n"
         "h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #ccc;margin-top:1.6em}\n"
         "h3{font-size:1.05em}\n"
         "table{border-collapse:collapse;margin:.5em 0;font-size:.9em}td,th{border:1px solid #ccc;"
         "padding:2px 6px;text-align:left;vertical-align:top}th{background:#f2f2f2}\n"
         "td.num{text-align:right;font-variant-numeric:tabular-nums}\n"
         "tr.result td{font-weight:bold}\n"
         ".banner{padding:.7em 1em;border-radius:4px;font-weight:bold}\n"
         ".failed{background:#fdd;border:2px solid #c00;color:#900}\n"
         ".converged{background:#e6f4e6;border:1px solid #6a6}\n"
         ".note{color:#555;font-size:.9em}svg{display:block;margin:.5em 0}\n"
         ".tick{font-size:11px}.wide{overflow-x:auto}.row{display:flex;flex-wrap:wrap;gap:1em}\n"
         "</style>\n</head>\n<body>\n" +
         body + "</body>\n</html>\n";
}

}  // namespace hpcontact::post
