#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

namespace slamsweep::report::inline html {

/// `text` with & < > " ' replaced by entities: safe inside element content and quoted attributes.
std::string EscapeHtml(std::string_view text);

/// A fragment of HTML. The only ways to make one are Escape (from untrusted text) and Trusted
/// (markup the report itself writes), so a value from a result file cannot reach a page unescaped
/// by accident: page code has no way to splice a plain std::string into a template.
class Html {
 public:
  Html() = default;
  static Html Escape(std::string_view text) { return Html(EscapeHtml(text)); }
  /// Markup written by the report (tags, attributes); never call with data read from files.
  static Html Trusted(std::string_view markup) { return Html(std::string(markup)); }
  const std::string& str() const { return html_; }
  Html& operator+=(const Html& other) {
    html_ += other.html_;
    return *this;
  }
  friend Html operator+(Html a, const Html& b) { return a += b; }

 private:
  explicit Html(std::string html) : html_(std::move(html)) {}
  std::string html_;
};

/// Short names for page code: T for the report's own markup, E for text read from files.
namespace html_shorthand {
inline Html T(std::string_view markup) { return Html::Trusted(markup); }
inline Html E(std::string_view text) { return Html::Escape(text); }
}  // namespace html_shorthand

/// A named value for RenderTemplate.
struct TemplateField {
  std::string_view name;
  Html value;
};

/// Replaces every `{{name}}` in `page_template` by the field of that name. A placeholder
/// without a field, or a field without a placeholder, is a programming error (std::logic_error),
/// so templates and page code cannot drift apart silently.
Html RenderTemplate(std::string_view page_template, std::initializer_list<TemplateField> fields);

/// `<tag class="css_class">escaped text</tag>`; no class attribute when `css_class` is empty.
Html Element(std::string_view tag, std::string_view css_class, const Html& content);

/// `<a href="...">content</a>` with the (relative, report-internal) href escaped.
Html Link(std::string_view href, const Html& content);

}  // namespace slamsweep::report::inline html
