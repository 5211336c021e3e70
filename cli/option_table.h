// The command line as tables: one row per option, each with its name, its value's name, its range
// and unit, its help, how it sets the command and how the report echoes it. The help text, the
// parser and report.json's list of options are all generated from the rows, so they cannot
// disagree (cli/command_line.cpp holds the tables).
#pragma once

#include <cmath>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "base/errors.h"

namespace radbake {

// A mistake in the arguments: exit status 2, and the message names the option.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Whether an option changes what the bake computes (and so a checkpoint's fingerprint), or only
// how the run goes: threads, where files go, checkpoints, what is printed.
enum class Affects { Result, Run };

template <class Target>
struct Option {
  std::string name;        // "--gather-rays"
  std::string value;       // the value's name in the help, "N"; empty: a flag
  std::string range;       // "1..1048576 rays", shown in the help; empty: none to show
  std::string help;        // what it does; the help adds the range and the default
  std::string default_note;  // said after the default ("auto: about ..."); empty: the default alone
  std::function<void(Target&, const std::string&)> set;  // throws UsageError naming the option
  std::function<std::string(const Target&)> echo;        // the value in effect, as report.json lists it
  Affects affects = Affects::Result;
  bool first = false;      // applied before the others wherever it stands (a preset they override)
  std::string alias;       // a short spelling, "-o"
  bool show_default = true;
};

template <class Target>
struct OptionGroup {
  std::string title;  // "lightmap UV options (bake and uv):", or a paragraph that opens the group
  std::vector<Option<Target>> options;
};

// Every option of a command, in the order its help lists them.
template <class Target>
using OptionTable = std::vector<OptionGroup<Target>>;

// ---- Values, as every row parses and prints them ----

// `text` clipped for a message, as ", got 'text'".
std::string got(const std::string& text);
// A number as the help and the messages print a bound: whole numbers without exponent.
std::string bound_text(double v);
// A value as report.json lists it (iostream's default format: 1024, 0.001, 1e-05).
std::string echo_number(double v);
// Throws UsageError "option NAME needs a number" / "must be between LO and HI".
double parse_number(const std::string& option, const std::string& text, double lo, double hi);
long parse_integer(const std::string& option, const std::string& text, long lo, long hi);
// "a,b,c" as `count` numbers in [lo, hi].
std::vector<double> parse_numbers(const std::string& option, const std::string& text, size_t count, double lo,
                                  double hi);
// "a, b or c".
std::string one_of(const std::vector<std::string>& words);
// One option in the help: "  NAME VALUE" in a column of 24, `help` wrapped beside it.
std::string option_line(const std::string& name, const std::string& help);

// ---- Rows ----
// `field` is a lambda from the target to the field the row sets, written for both a const and a
// mutable target: [](auto& c) -> auto& { return c.bake.gather.rays; }.

// A row's words: what --help shows of it.
template <class Target>
Option<Target> row(std::string name, std::string value, std::string help, std::string range = "") {
  Option<Target> o;
  o.name = std::move(name);
  o.value = std::move(value);
  o.help = std::move(help);
  o.range = std::move(range);
  return o;
}

// "LO..HI UNIT", as the help shows a range.
std::string range_text(double lo, double hi, const std::string& unit);

// A number in [lo, hi] (whole for an integer field), `unit` after the range in the help.
template <class Target, class Field>
Option<Target> number(std::string name, std::string value, double lo, double hi, std::string unit, Field field,
                      std::string help) {
  Option<Target> o = row<Target>(name, std::move(value), std::move(help), range_text(lo, hi, unit));
  o.set = [name, lo, hi, field](Target& t, const std::string& v) {
    auto& f = field(t);
    using T = std::remove_reference_t<decltype(f)>;
    if constexpr (std::is_integral_v<T>) f = T(parse_integer(name, v, long(lo), long(hi)));
    else f = T(parse_number(name, v, lo, hi));
  };
  o.echo = [field](const Target& t) { return echo_number(double(field(t))); };
  return o;
}

// A number in [lo, hi], or "auto" (held as 0, echoed as "auto").
template <class Target, class Field>
Option<Target> number_or_auto(std::string name, std::string value, double lo, double hi, std::string unit, Field field,
                              std::string help) {
  Option<Target> o = number<Target>(name, std::move(value), lo, hi, std::move(unit), field, std::move(help));
  auto set_number = o.set;
  o.set = [set_number, field](Target& t, const std::string& v) {
    if (v == "auto") field(t) = 0;
    else set_number(t, v);
  };
  o.echo = [field](const Target& t) { return field(t) > 0 ? echo_number(double(field(t))) : std::string("auto"); };
  return o;
}

// A number in [lo, hi] held in a std::optional, which stays empty (echoed "none") unless given.
template <class Target, class Field>
Option<Target> optional_number(std::string name, std::string value, double lo, double hi, std::string unit, Field field,
                               std::string help) {
  Option<Target> o = row<Target>(name, std::move(value), std::move(help), range_text(lo, hi, unit));
  o.set = [name, lo, hi, field](Target& t, const std::string& v) { field(t) = parse_number(name, v, lo, hi); };
  o.echo = [field](const Target& t) { return field(t) ? echo_number(*field(t)) : std::string("none"); };
  o.show_default = false;
  return o;
}

// One of some words, each naming a value of the field; the help's text says what each does.
template <class Target, class Field, class Value>
Option<Target> choice(std::string name, std::string value, std::vector<std::pair<std::string, Value>> words,
                      Field field, std::string help) {
  Option<Target> o = row<Target>(name, std::move(value), std::move(help));
  std::vector<std::string> names;
  for (const auto& w : words) names.push_back(w.first);
  const std::string allowed = one_of(names);
  o.set = [name, words, allowed, field](Target& t, const std::string& v) {
    for (const auto& w : words)
      if (w.first == v) {
        field(t) = w.second;
        return;
      }
    throw UsageError("option " + name + " must be " + allowed + got(v));
  };
  o.echo = [words, field](const Target& t) {
    for (const auto& w : words)
      if (w.second == field(t)) return w.first;
    return std::string("none");  // a value no word names: the field's unset state
  };
  return o;
}

// A flag that sets a bool field to `when_given`; echoed "yes" when it is in effect.
template <class Target, class Field>
Option<Target> flag(std::string name, bool when_given, Field field, std::string help) {
  Option<Target> o = row<Target>(std::move(name), "", std::move(help));
  o.set = [when_given, field](Target& t, const std::string&) { field(t) = when_given; };
  o.echo = [when_given, field](const Target& t) { return std::string(field(t) == when_given ? "yes" : "no"); };
  o.show_default = false;
  return o;
}

// A text kept as it is (a path, a file); echoed "none" while empty.
template <class Target, class Field>
Option<Target> text(std::string name, std::string value, Field field, std::string help) {
  Option<Target> o = row<Target>(std::move(name), std::move(value), std::move(help));
  o.set = [field](Target& t, const std::string& v) { field(t) = v; };
  o.echo = [field](const Target& t) { return field(t).empty() ? std::string("none") : field(t); };
  o.show_default = false;
  return o;
}

// A table of another target, set through the member `part` (the reading options of `bake` and `uv`).
template <class Whole, class Part>
OptionGroup<Whole> lifted(const OptionGroup<Part>& group, Part Whole::*part) {
  OptionGroup<Whole> whole{group.title, {}};
  for (const Option<Part>& o : group.options) {
    Option<Whole> w;
    w.name = o.name, w.value = o.value, w.range = o.range, w.help = o.help, w.default_note = o.default_note;
    w.affects = o.affects, w.first = o.first, w.alias = o.alias, w.show_default = o.show_default;
    w.set = [set = o.set, part](Whole& t, const std::string& v) { set(t.*part, v); };
    w.echo = [echo = o.echo, part](const Whole& t) { return echo(t.*part); };
    whole.options.push_back(std::move(w));
  }
  return whole;
}

// ---- What the tables make ----

// Reads `args` from position 1 into `target`: options by the table (NAME VALUE, NAME=VALUE, flags;
// rows marked `first` before the others), other arguments to `positional`. Returns false when
// -h or --help asked for the help instead.
template <class Target>
bool parse_options(const std::vector<std::string>& args, const OptionTable<Target>& table, Target& target,
                   const std::function<void(const std::string&)>& positional) {
  std::vector<std::pair<const Option<Target>*, std::string>> given;
  auto find = [&](const std::string& arg) -> const Option<Target>* {
    for (const OptionGroup<Target>& g : table)
      for (const Option<Target>& o : g.options)
        if (arg == o.name || (!o.alias.empty() && arg == o.alias)) return &o;
    return nullptr;
  };
  for (size_t i = 1; i < args.size(); ++i) {
    std::string arg = args[i];
    if (arg == "-h" || arg == "--help") return false;
    if (arg.empty() || arg[0] != '-') {
      positional(arg);
      continue;
    }
    std::string value;
    bool inline_value = false;
    if (size_t eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      inline_value = true;
    }
    const Option<Target>* o = find(arg);
    if (!o) throw UsageError("unknown option " + clipped(arg) + " (see radbake --help)");
    if (o->value.empty() && inline_value) throw UsageError("option " + o->name + " takes no value" + got(value));
    if (!o->value.empty() && !inline_value) {
      if (i + 1 >= args.size()) throw UsageError("option " + o->name + " needs a value");
      value = args[++i];
    }
    given.push_back({o, value});
  }
  for (bool first : {true, false})
    for (const auto& [o, value] : given)
      if (o->first == first) o->set(target, value);
  return true;
}

// The help lines of a table's options, the defaults read from `defaults`: each option's name and
// value in a column, its help wrapped beside it.
template <class Target>
std::string options_help(const OptionTable<Target>& table, const Target& defaults) {
  std::string out;
  for (const OptionGroup<Target>& g : table) {
    out += "\n" + g.title + "\n";
    for (const Option<Target>& o : g.options) {
      std::string what = o.help;
      std::string bracket = o.range;
      if (o.show_default) {
        const std::string d = o.echo(defaults);
        bracket += (bracket.empty() ? "" : "; ") + std::string("default ") + d +
                   (o.default_note.empty() ? "" : ": " + o.default_note);
      } else if (!o.default_note.empty()) {
        bracket += (bracket.empty() ? "" : "; ") + o.default_note;
      }
      if (!bracket.empty()) what += " (" + bracket + ")";
      out += option_line((o.alias.empty() ? "" : o.alias + ", ") + o.name + (o.value.empty() ? "" : " " + o.value), what);
    }
  }
  return out;
}

// What report.json lists: every option and the value in effect, by name without its dashes.
// With `affects`, only the options that affect that.
template <class Target>
std::vector<std::pair<std::string, std::string>> echo_options(const OptionTable<Target>& table, const Target& target,
                                                              const Affects* affects = nullptr) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const OptionGroup<Target>& g : table)
    for (const Option<Target>& o : g.options)
      if (!affects || o.affects == *affects) out.push_back({o.name.substr(2), o.echo(target)});
  return out;
}

}  // namespace radbake
