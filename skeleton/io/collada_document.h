#pragma once
// A parsed COLLADA file for the importer: element paths for messages, checked
// numbers from element text, "#id" references, and bounded warnings.
// Internal to the scene loader (pugixml is a private dependency of the skeleton
// library, so keep this header out of public ones).
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <pugixml.hpp>

#include "core/vec.h"

namespace pt {

using XmlNode = pugi::xml_node;

class ColladaDocument {
 public:
  // Reads and parses `path`. Throws SceneError "path: cannot open (...)" and,
  // for malformed XML, "path:LINE:COL: XML syntax error: ...". At most
  // `max_warnings` warnings are kept (the rest are counted, see finish()).
  ColladaDocument(std::string path, std::vector<std::string>* warnings, size_t max_warnings);

  XmlNode root() const { return doc_.document_element(); }
  const std::string& file() const { return path_; }

  // Where an element is, as an XPath: elements with an id are named by it,
  // repeated siblings by their 1-based position:
  // "/COLLADA/library_geometries/geometry[@id='box']/mesh/polylist[2]".
  // With by_id false, by positions only (two elements with one id differ).
  static std::string path_of(XmlNode e, bool by_id = true);
  // A name or attribute value fit for a message: printable, at most 60 chars.
  static std::string quoted(std::string_view s);

  // Throws SceneError "file: <path of at>: message".
  [[noreturn]] void fail(XmlNode at, const std::string& message) const;
  // Records "<path of at>: message" (the command line prefixes the file).
  void warn(XmlNode at, const std::string& message);
  // Adds "... N more warnings" when some were dropped.
  void finish();

  // The element that at's attribute `attribute` ("#id") names; it must be a
  // <kind>. Fails when the reference is missing, external, unknown or of
  // another kind.
  XmlNode resolve(XmlNode at, const char* attribute, const char* kind) const;

  // The child element `name` of e; fails when there is none.
  XmlNode child(XmlNode e, const char* name) const;

  // The numbers in e's text, each finite and at most 1e30 in magnitude.
  std::vector<double> numbers(XmlNode e) const;
  // Exactly n of them (fails naming how many there are).
  std::vector<double> numbers(XmlNode e, size_t n) const;
  double number(XmlNode e) const { return numbers(e, 1)[0]; }
  Vec3 vec3(XmlNode e) const;
  // A colour: 3 numbers, or 4 with an alpha that is ignored; none negative.
  Spectrum color(XmlNode e) const;
  // Non-negative integers below 2^32 in e's text (indices and counts).
  std::vector<uint32_t> integers(XmlNode e) const;
  // A non-negative integer attribute; fails when absent unless a fallback is given.
  uint64_t integer_attribute(XmlNode e, const char* name) const;
  uint64_t integer_attribute(XmlNode e, const char* name, uint64_t fallback) const;

 private:
  // e's character data (all of its text pieces); fails if e has child elements.
  std::string_view text(XmlNode e, std::string* storage) const;
  template <class T, class InRange>
  std::vector<T> parse_all(XmlNode e, const char* kind, InRange in_range, const char* range) const;

  std::string path_;
  pugi::xml_document doc_;
  std::unordered_map<std::string_view, XmlNode> ids_;
  std::vector<std::string>* warnings_;
  size_t max_warnings_, dropped_warnings_ = 0;
};

}  // namespace pt
