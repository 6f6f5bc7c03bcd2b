#pragma once
// A key table: every key of a case table declared once, against the member of
// the plain struct it fills — name, member, type, allowed range, unit, default
// (the member's initializer, or a default computed from keys read before it)
// and a one-line meaning. From the table alone:
//   read(c, spec)    the typed, range-checked getters of Config (errors name
//                    file, key, value and what is allowed), in table order;
//   schema(prefix)   the rows of `--help`, "did you mean", completion and
//                    docs/keys.md.
// Checks between keys stay in the struct's validate().
//
//   static const auto table = KeyTable<Setup>()
//       .number("size", &Setup::size, Range::positive(), units::length, "side L of the cell")
//       .integer("grid", &Setup::grid, Range::closed(8, 4096), "cells per side");
//
// A member is a pointer to member or any callable giving a reference into the
// struct (`[](Setup& s) -> double& { return s.inner.size; }`).
#include <filesystem>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "wearscale/core/range.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/key_spec.hpp"

namespace wearscale {

namespace key_table_detail {
std::string default_text(double v);
std::string joined_choices(const std::vector<std::string>& names);
std::string joined(const std::vector<std::string>& texts, const std::string& separator);
}  // namespace key_table_detail

template <class Spec>
class KeyTable {
 public:
  /// One declared key: its row (key relative to the table) and how it is read.
  struct Key {
    KeySpec row;
    bool required = false;
    bool fallback_given = false;  ///< row.fallback set by fallback() or a computed default
    Range range;
    units::Dimension dimension = units::dimensionless;
    std::function<Range(const Spec&)> range_of;            ///< a range from keys read before
    std::function<double(const Spec&)> number_default;     ///< a default from keys read before
    std::function<std::string(const Spec&)> text_default;  ///< a choice's default from keys read before
    std::function<bool(const Config&, const Spec&)> read_if;  ///< read only when this holds
    std::function<void(const Key&, const Config&, Spec&)> read;
    std::function<std::string(Spec&)> default_of;  ///< the member's default as text

    std::function<bool(const Spec&)> required_when;  ///< required or not by the keys read before
    Range range_for(const Spec& s) const { return range_of ? range_of(s) : range; }
    bool required_for(const Spec& s) const { return required || (required_when && required_when(s)); }
  };

  /// A number in SI; a string with a unit of dimension `dim` is converted.
  template <class At>
  KeyTable& number(std::string key, At at, Range range, units::Dimension dim, std::string doc) {
    Key k = make(std::move(key), "number", range.describe(), dim.to_string(), std::move(doc));
    k.range = range;
    k.dimension = dim;
    k.read = [at](const Key& self, const Config& c, Spec& s) {
      const Range r = self.range_for(s);
      double& v = std::invoke(at, s);
      const std::string& name = self.row.key;
      if (self.required_for(s))
        v = c.number(name, r, self.dimension);
      else
        v = c.number_or(name, self.number_default ? self.number_default(s) : v, r, self.dimension);
    };
    k.default_of = [at](Spec& s) { return key_table_detail::default_text(std::invoke(at, s)); };
    return add(std::move(k));
  }
  template <class At>
  KeyTable& number(std::string key, At at, Range range, std::string doc) {
    return number(std::move(key), at, range, units::dimensionless, std::move(doc));
  }

  /// An integer (any integral member).
  template <class At>
  KeyTable& integer(std::string key, At at, Range range, std::string doc) {
    Key k = make(std::move(key), "integer", range.describe(), "", std::move(doc));
    k.range = range;
    k.read = [at](const Key& self, const Config& c, Spec& s) {
      auto& v = std::invoke(at, s);
      using I = std::remove_reference_t<decltype(v)>;
      const Range r = self.range_for(s);
      const long fallback = self.number_default ? std::lround(self.number_default(s)) : static_cast<long>(v);
      v = static_cast<I>(self.required_for(s) ? c.integer(self.row.key, r) : c.integer_or(self.row.key, fallback, r));
    };
    k.default_of = [at](Spec& s) { return fmt::format("{}", std::invoke(at, s)); };
    return add(std::move(k));
  }

  /// A number that may be absent (a std::optional<double> member, empty when
  /// it is); give its meaning when absent with fallback().
  template <class At>
  KeyTable& optional_number(std::string key, At at, Range range, units::Dimension dim, std::string doc) {
    Key k = make(std::move(key), "number", range.describe(), dim.to_string(), std::move(doc));
    k.range = range;
    k.dimension = dim;
    k.read = [at](const Key& self, const Config& c, Spec& s) {
      std::optional<double>& v = std::invoke(at, s);
      c.mark_used(self.row.key);
      if (c.has(self.row.key)) v = c.number(self.row.key, self.range_for(s), self.dimension);
    };
    k.default_of = [](Spec&) { return std::string(); };
    return add(std::move(k));
  }

  /// A non-empty array of numbers in SI (strings with a unit of dimension
  /// `dim` converted), each in `range`; absent: the member's initializer.
  template <class At>
  KeyTable& numbers(std::string key, At at, Range range, units::Dimension dim, std::string doc) {
    Key k = make(std::move(key), "list", range.describe(), dim.to_string(), std::move(doc));
    k.range = range;
    k.dimension = dim;
    k.read = [at](const Key& self, const Config& c, Spec& s) {
      std::vector<double>& v = std::invoke(at, s);
      const std::string& name = self.row.key;
      c.mark_used(name);
      if (!self.required_for(s) && !c.has(name)) return;
      const Range r = self.range_for(s);
      v = c.numbers(name, r, self.dimension);
      if (v.empty())
        throw c.error(name, "an empty list",
                      "a non-empty array of numbers in " + r.describe() +
                          (self.dimension == units::dimensionless ? "" : " " + self.dimension.to_string()));
    };
    k.default_of = [at](Spec& s) {
      std::vector<std::string> texts;
      for (double x : std::invoke(at, s)) texts.push_back(key_table_detail::default_text(x));
      return "[" + key_table_detail::joined(texts, ", ") + "]";
    };
    return add(std::move(k));
  }

  /// Names: an array of strings, or one string; absent: the member's initializer.
  template <class At>
  KeyTable& names(std::string key, At at, std::string doc) {
    Key k = make(std::move(key), "list", "an array of names, or one name", "", std::move(doc));
    k.read = [at](const Key& self, const Config& c, Spec& s) {
      std::vector<std::string>& v = std::invoke(at, s);
      const std::string& name = self.row.key;
      c.mark_used(name);
      if (!self.required_for(s) && !c.has(name)) return;
      try {
        v = c.values_as_text(name);
      } catch (const InputError&) {
        try {
          v = {c.string(name)};
        } catch (const InputError&) {
          throw c.error(name, "not a list of names", "an array of names, or one name");
        }
      }
    };
    k.default_of = [at](Spec& s) {
      const auto& v = std::invoke(at, s);
      return v.empty() ? std::string("[]") : "[\"" + key_table_detail::joined(v, "\", \"") + "\"]";
    };
    return add(std::move(k));
  }

  template <class At>
  KeyTable& boolean(std::string key, At at, std::string doc) {
    Key k = make(std::move(key), "boolean", "true | false", "", std::move(doc));
    k.read = [at](const Key& self, const Config& c, Spec& s) {
      bool& v = std::invoke(at, s);
      v = self.required_for(s) ? c.boolean(self.row.key) : c.boolean_or(self.row.key, v);
    };
    k.default_of = [at](Spec& s) { return std::invoke(at, s) ? std::string("true") : std::string("false"); };
    return add(std::move(k));
  }

  /// A string (a name; "" is a value like any other).
  template <class At>
  KeyTable& string(std::string key, At at, std::string doc) {
    Key k = make(std::move(key), "string", "", "", std::move(doc));
    k.read = [at](const Key& self, const Config& c, Spec& s) {
      std::string& v = std::invoke(at, s);
      v = self.required_for(s) ? c.string(self.row.key)
                        : c.string_or(self.row.key, self.text_default ? self.text_default(s) : v);
    };
    k.default_of = [at](Spec& s) { return std::string(std::invoke(at, s)); };
    return add(std::move(k));
  }

  /// One of `values`' names, stored as its value (an enum, or the name itself).
  template <class At, class E>
  KeyTable& choice(std::string key, At at, std::vector<std::pair<std::string, E>> values, std::string doc) {
    std::vector<std::string> names;
    for (const auto& [name, value] : values) names.push_back(name);
    Key k = make(std::move(key), "choice", key_table_detail::joined_choices(names), "", std::move(doc));
    const auto name_of = [values](const E& e) {
      for (const auto& [name, value] : values)
        if (value == e) return name;
      throw std::logic_error("a key table's choice holds a value it does not name");
    };
    k.read = [at, values, names, name_of](const Key& self, const Config& c, Spec& s) {
      auto& v = std::invoke(at, s);
      const std::string text = self.required_for(s) ? c.choice(self.row.key, names)
                                             : c.choice_or(self.row.key,
                                                           self.text_default ? self.text_default(s) : name_of(v),
                                                           names);
      for (const auto& [name, value] : values)
        if (name == text) v = value;
    };
    k.default_of = [at, name_of](Spec& s) { return name_of(std::invoke(at, s)); };
    return add(std::move(k));
  }
  template <class At>
  KeyTable& choice(std::string key, At at, const std::vector<std::string>& names, std::string doc) {
    std::vector<std::pair<std::string, std::string>> values;
    for (const auto& n : names) values.emplace_back(n, n);
    return choice(std::move(key), at, std::move(values), std::move(doc));
  }

  /// A file name, relative to the case file's folder (Config::path); required.
  template <class At>
  KeyTable& path(std::string key, At at, std::string doc) {
    Key k = make(std::move(key), "path", "a file name, relative to the case file's folder", "", std::move(doc));
    k.required = true;
    k.read = [at](const Key& self, const Config& c, Spec& s) { std::invoke(at, s) = c.path(self.row.key); };
    k.default_of = [](Spec&) { return std::string(); };
    return add(std::move(k));
  }

  /// A non-empty array of numbers or strings, each as text (Config::values_as_text); required.
  template <class At>
  KeyTable& texts(std::string key, At at, std::string doc) {
    Key k = make(std::move(key), "list", "an array of numbers or strings", "", std::move(doc));
    k.required = true;
    k.read = [at](const Key& self, const Config& c, Spec& s) { std::invoke(at, s) = c.values_as_text(self.row.key); };
    k.default_of = [](Spec&) { return std::string(); };
    return add(std::move(k));
  }

  /// A key read by its own reader `read(c, key, spec)`, for a value no other
  /// kind describes (`type`, `allowed` and `unit` as the docs show them);
  /// give its default with fallback().
  KeyTable& custom(std::string key, std::string type, std::string allowed, std::string unit, std::string doc,
                   std::function<void(const Config&, const std::string&, Spec&)> reader) {
    Key k = make(std::move(key), std::move(type), std::move(allowed), std::move(unit), std::move(doc));
    k.read = [reader](const Key& self, const Config& c, Spec& s) {
      c.mark_used(self.row.key);
      reader(c, self.row.key, s);
    };
    k.default_of = [](Spec&) { return std::string(); };
    return add(std::move(k));
  }

  /// A sub-table read by its own reader `read(c, spec)` (`c`: this table's view).
  KeyTable& table(std::string key, std::string doc, std::function<void(const Config&, Spec&)> reader,
                  std::string allowed = {}) {
    Key k = make(std::move(key), "table", std::move(allowed), "", std::move(doc));
    k.read = [reader](const Key&, const Config& c, Spec& s) { reader(c, s); };
    k.default_of = [](Spec&) { return std::string(); };
    k.fallback_given = true;
    return add(std::move(k));
  }

  // --- Refinements of the key declared last ---------------------------------
  /// No default: an absent key is an error.
  KeyTable& required() {
    last().required = true;
    return *this;
  }
  /// Required when `when` holds on the keys read before (else its default applies).
  KeyTable& required_when(std::function<bool(const Spec&)> when) {
    last().required_when = std::move(when);
    return *this;
  }
  /// The default as the docs show it, for one the member's initializer does not give.
  KeyTable& fallback(std::string text) {
    last().row.fallback = std::move(text);
    last().fallback_given = true;
    return *this;
  }
  /// A default computed from the keys read before (`text` says how, for the docs).
  KeyTable& computed_default(std::function<double(const Spec&)> f, std::string text) {
    last().number_default = std::move(f);
    return fallback(std::move(text));
  }
  KeyTable& computed_text(std::function<std::string(const Spec&)> f, std::string text) {
    last().text_default = std::move(f);
    return fallback(std::move(text));
  }
  /// The allowed values in words, for a key whose type does not say them all.
  KeyTable& allowed(std::string text) {
    last().row.range = std::move(text);
    return *this;
  }
  /// The unit as the docs write it ("K/s"), for one its dimension spells otherwise.
  KeyTable& unit(std::string text) {
    last().row.unit = std::move(text);
    return *this;
  }
  /// The command-line alias of the key ("--d0"); `switch_value`: what the
  /// alias sets when given without a value ("--no-strengths": "false").
  KeyTable& flag(std::string alias, std::string switch_value = {}) {
    last().row.flag = std::move(alias);
    last().row.switch_value = std::move(switch_value);
    return *this;
  }
  /// A range from the keys read before (`text` says which, for the docs).
  KeyTable& range_from(std::function<Range(const Spec&)> f, std::string text) {
    last().range_of = std::move(f);
    last().row.range = std::move(text);
    return *this;
  }
  /// Read only when `when` holds (a key of an optional table); else neither read nor defaulted.
  KeyTable& read_if(std::function<bool(const Config&, const Spec&)> when) {
    last().read_if = std::move(when);
    return *this;
  }

  /// A check between the keys declared so far (the struct's validate()), run
  /// at this point of read(), before the keys declared after it are read.
  KeyTable& then(std::function<void(const Config&, Spec&)> step) {
    steps_.emplace_back(keys_.size(), std::move(step));
    return *this;
  }

  // --- Use ----------------------------------------------------------------
  /// Reads every key into `spec`, in table order (with the checks between
  /// them); InputError on a bad value.
  void read(const Config& c, Spec& spec) const {
    auto step = steps_.begin();
    for (std::size_t i = 0; i <= keys_.size(); ++i) {
      for (; step != steps_.end() && step->first == i; ++step) step->second(c, spec);
      if (i == keys_.size()) break;
      const Key& k = keys_[i];
      if (!k.read_if || k.read_if(c, spec)) k.read(k, c, spec);
    }
  }
  /// The rows of the table's keys, each named `prefix` + "." + key (no prefix: the key).
  Schema schema(const std::string& prefix = {}) const {
    Schema out;
    for (const auto& k : keys_) {
      KeySpec row = k.row;
      if (!prefix.empty()) row.key = prefix + "." + row.key;
      if (!k.fallback_given) {
        Spec fresh{};
        row.fallback = k.required ? std::string() : k.default_of(fresh);
      }
      out.push_back(std::move(row));
    }
    return out;
  }
  const std::vector<Key>& keys() const { return keys_; }
  /// The declared key `name`; std::logic_error if there is none.
  const Key& key(const std::string& name) const {
    for (const auto& k : keys_)
      if (k.row.key == name) return k;
    throw std::logic_error("key '" + name + "' is not declared in its key table");
  }

 private:
  static Key make(std::string key, std::string type, std::string range, std::string unit, std::string doc) {
    Key k;
    k.row.key = std::move(key);
    k.row.type = std::move(type);
    k.row.range = std::move(range);
    k.row.unit = std::move(unit);
    k.row.doc = std::move(doc);
    return k;
  }
  KeyTable& add(Key k) {
    for (const auto& other : keys_)
      if (other.row.key == k.row.key) throw std::logic_error("key '" + k.row.key + "' declared twice");
    keys_.push_back(std::move(k));
    return *this;
  }
  Key& last() {
    if (keys_.empty()) throw std::logic_error("a key table's refinement before any key");
    return keys_.back();
  }
  std::vector<Key> keys_;
  std::vector<std::pair<std::size_t, std::function<void(const Config&, Spec&)>>> steps_;
};

}  // namespace wearscale
