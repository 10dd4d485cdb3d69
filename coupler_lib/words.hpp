#pragma once
// Choice words and the enums they stand for. A scene's choice keys (and clump_gen's --shape) are
// read as words; each enum's table below is the one list of its words: the schema's allowed
// values are taken from it (words_of) and the reader turns the word into the enum at parse time
// (value_of), so no code past the reader compares strings.
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lbdem {

template <class E>
struct Word {
  std::string_view text;
  E value;
};

template <class E, std::size_t N>
using WordTable = std::array<Word<E>, N>;

// The words, in the table's order (the schema's allowed values).
template <class E, std::size_t N>
std::vector<std::string> words_of(const WordTable<E, N>& table) {
  std::vector<std::string> out;
  for (const Word<E>& w : table) out.emplace_back(w.text);
  return out;
}

template <class E, std::size_t N>
std::optional<E> find_word(const WordTable<E, N>& table, std::string_view text) {
  for (const Word<E>& w : table)
    if (w.text == text) return w.value;
  return std::nullopt;
}

// The value of a word the reader has already checked against the table's words.
template <class E, std::size_t N>
E value_of(const WordTable<E, N>& table, std::string_view text) {
  if (const auto v = find_word(table, text)) return *v;
  throw std::logic_error("choice word '" + std::string(text) + "' is not in its table");
}

template <class E, std::size_t N>
std::string_view word_of(const WordTable<E, N>& table, E value) {
  for (const Word<E>& w : table)
    if (w.value == value) return w.text;
  throw std::logic_error("choice value without a word in its table");
}

}  // namespace lbdem
