#include "report/html/html.h"

#include <stdexcept>
#include <vector>

namespace slamsweep::report::inline html {

std::string EscapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

Html RenderTemplate(std::string_view page_template, std::initializer_list<TemplateField> fields) {
  std::vector<bool> used(fields.size(), false);
  std::string out;
  out.reserve(page_template.size() * 2);
  std::size_t pos = 0;
  while (pos < page_template.size()) {
    const std::size_t open = page_template.find("{{", pos);
    if (open == std::string_view::npos) {
      out.append(page_template.substr(pos));
      break;
    }
    const std::size_t close = page_template.find("}}", open + 2);
    if (close == std::string_view::npos) throw std::logic_error("template: '{{' without '}}'");
    out.append(page_template.substr(pos, open - pos));
    const std::string_view name = page_template.substr(open + 2, close - open - 2);
    bool found = false;
    std::size_t i = 0;
    for (const TemplateField& field : fields) {
      if (field.name == name) {
        out += field.value.str();
        used[i] = true;
        found = true;
        break;
      }
      ++i;
    }
    if (!found) throw std::logic_error("template: no value for {{" + std::string(name) + "}}");
    pos = close + 2;
  }
  std::size_t i = 0;
  for (const TemplateField& field : fields) {
    if (!used[i++]) throw std::logic_error("template: no placeholder {{" + std::string(field.name) + "}}");
  }
  return Html::Trusted(out);
}

Html Element(std::string_view tag, std::string_view css_class, const Html& content) {
  // Built with append: GCC 12 reports a false -Wrestrict for `"literal" + std::string`.
  std::string open = "<";
  open.append(tag);
  if (!css_class.empty()) open.append(" class=\"").append(EscapeHtml(css_class)).append("\"");
  open += '>';
  std::string close = "</";
  close.append(tag).append(">");
  return Html::Trusted(open) + content + Html::Trusted(close);
}

Html Link(std::string_view href, const Html& content) {
  return Html::Trusted("<a href=\"" + EscapeHtml(href) + "\">") + content + Html::Trusted("</a>");
}

}  // namespace slamsweep::report::inline html
