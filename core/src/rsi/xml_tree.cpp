// SPDX-License-Identifier: Apache-2.0
// XmlElement trees from expat's callbacks (xml_tree.h).
#include "rsi/xml_tree.h"

#include <expat.h>

#include <fstream>
#include <memory>
#include <sstream>

namespace xmate::rsi {
namespace {

std::string trimmed(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

// The parse in progress: a stack of open elements (the root first).
struct Builder {
  XML_Parser parser = nullptr;
  std::vector<XmlElement*> open;
  XmlElement root;
  bool have_root = false;
};

void XMLCALL startElement(void* data, const XML_Char* name, const XML_Char** attributes) {
  auto& b = *static_cast<Builder*>(data);
  XmlElement element;
  element.name = name;
  element.line = int(XML_GetCurrentLineNumber(b.parser));
  for (const XML_Char** a = attributes; *a; a += 2) element.attributes.emplace_back(a[0], a[1]);
  if (b.open.empty()) {
    b.root = std::move(element);
    b.have_root = true;
    b.open.push_back(&b.root);
  } else {
    b.open.back()->children.push_back(std::move(element));
    b.open.push_back(&b.open.back()->children.back());
  }
}

void XMLCALL endElement(void* data, const XML_Char*) {
  auto& b = *static_cast<Builder*>(data);
  b.open.back()->text = trimmed(b.open.back()->text);
  b.open.pop_back();
}

void XMLCALL characters(void* data, const XML_Char* s, int length) {
  auto& b = *static_cast<Builder*>(data);
  if (!b.open.empty()) b.open.back()->text.append(s, size_t(length));
}

}  // namespace

const std::string* XmlElement::attribute(std::string_view attribute_name) const {
  for (const auto& [key, value] : attributes)
    if (key == attribute_name) return &value;
  return nullptr;
}

const XmlElement* XmlElement::child(std::string_view child_name) const {
  for (const XmlElement& c : children)
    if (c.name == child_name) return &c;
  return nullptr;
}

XmlElement parseXml(std::string_view text, const std::string& name) {
  std::unique_ptr<std::remove_pointer_t<XML_Parser>, decltype(&XML_ParserFree)> parser(XML_ParserCreate("UTF-8"),
                                                                                     &XML_ParserFree);
  if (!parser) throw ConfigError(name + ": cannot start the XML parser (out of memory)");
  Builder builder;
  builder.parser = parser.get();
  // The open stack points into the children vectors: safe, because only the innermost open
  // element's vector grows, and the elements it would move are all closed.
  XML_SetUserData(parser.get(), &builder);
  XML_SetElementHandler(parser.get(), startElement, endElement);
  XML_SetCharacterDataHandler(parser.get(), characters);
  if (XML_Parse(parser.get(), text.data(), int(text.size()), XML_TRUE) == XML_STATUS_ERROR)
    throw ConfigError(name + ":" + std::to_string(XML_GetCurrentLineNumber(parser.get())) + ": not well-formed XML (" +
                      XML_ErrorString(XML_GetErrorCode(parser.get())) + ", column " +
                      std::to_string(XML_GetCurrentColumnNumber(parser.get()) + 1) + ")");
  if (!builder.have_root) throw ConfigError(name + ": no XML element in the file");
  return std::move(builder.root);
}

std::string readTextFile(const std::string& path, const char* what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot open the " + what + "; check the path and that it is readable");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

XmlElement readXmlFile(const std::string& path) { return parseXml(readTextFile(path, "file"), path); }

}  // namespace xmate::rsi
