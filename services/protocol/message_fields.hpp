// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The bridge between a parameter table (core/numerics/parameter_table.hpp) and a message type:
/// per table key the message field that carries it (generated LCM types have no reflection, so
/// this list of names is the one place a key meets its field). The codecs fill and read messages
/// by walking the table; a key without a field is a programming error (std::logic_error), which
/// the round-trip tests of every table find.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/numerics/parameter_table.hpp"

namespace wrc::protocol {

/// One field of Message, named by the table key it carries.
template <class Message>
struct MessageField {
  const char* key;
  std::function<double(const Message&)> get;  ///< booleans (int8 0 / not 0) as 0 / 1
  std::function<void(Message&, double)> set;
};

/// The field `field` of Message carrying the table key `key`.
template <class Message, class V>
MessageField<Message> message_field(const char* key, V Message::*field) {
  return {key,
          [field](const Message& m) { return static_cast<double>(m.*field); },
          [field](Message& m, double v) { m.*field = static_cast<V>(v); }};
}

/// The field of Message with the same name as its key.
#define WRC_MESSAGE_FIELD(Message, name) ::wrc::protocol::message_field(#name, &Message::name)

/// The field of fields that carries key. @throws std::logic_error naming the key when none does.
template <class Message>
const MessageField<Message>& field_of(const std::vector<MessageField<Message>>& fields, const std::string& key) {
  for (const MessageField<Message>& f : fields)
    if (key == f.key) return f;
  throw std::logic_error("message field of table key '" + key + "' is not declared");
}

/// Fills the fields of m from every parameter of table.
template <class Message, class Entry, class T>
void to_message_fields(const std::vector<Entry>& table, const T& value,
                       const std::vector<MessageField<Message>>& fields, Message& m) {
  for (const Entry& p : table) field_of(fields, p.key).set(m, p.get(value));
}

/// Sets every parameter of table from m, each checked against its table's rule first.
/// @throws std::invalid_argument "<key> = <value> is outside <range> [<unit>]".
template <class Message, class Entry, class T>
void from_message_fields(const std::vector<Entry>& table, const Message& m,
                         const std::vector<MessageField<Message>>& fields, T& value) {
  for (const Entry& p : table) {
    double v = field_of(fields, p.key).get(m);
    if (p.kind == ParameterKind::kBoolean) v = v != 0.0 ? 1.0 : 0.0;
    if (const std::optional<std::string> why = p.violation(v)) throw std::invalid_argument(parameter_error(p, v, *why));
    p.set(value, v);
  }
}

}  // namespace wrc::protocol
