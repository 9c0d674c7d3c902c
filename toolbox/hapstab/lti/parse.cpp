#include "hapstab/lti/parse.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab {
namespace {

using RF = QRatFun;
using P = QPoly;

enum class Tok { number, name, plus, minus, star, slash, caret, lparen, rparen, end };

struct Token {
  Tok kind;
  std::string text;
  size_t column;  // 1-based
};

std::string describe(const Token& t) {
  switch (t.kind) {
    case Tok::end: return "end of expression";
    case Tok::number: return "number '" + t.text + "'";
    case Tok::name: return "name '" + t.text + "'";
    default: return "'" + t.text + "'";
  }
}

// The expression as messages show it: whole up to 120 characters, else a window around
// `column` with the cut ends marked.
std::string excerpt(std::string_view src, size_t column) {
  if (src.size() <= 120) return std::string(src);
  const size_t at = column == 0 ? 0 : std::min(column - 1, src.size());
  const size_t from = at > 60 ? at - 60 : 0, to = std::min(src.size(), from + 120);
  return (from > 0 ? "..." : "") + std::string(src.substr(from, to - from)) + (to < src.size() ? "..." : "");
}

// The end of the number starting at i ("12.5", "1e-3"), or i when none starts there.
size_t number_end(std::string_view s, size_t i) {
  if (!(std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) return i;
  size_t j = i;
  while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) ++j;
  // exponent only when 'e' is followed by digits (optionally signed): "1e-3", not "2e"
  if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
    size_t k = j + 1;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
    if (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) {
      while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
      j = k;
    }
  }
  return j;
}

// The end of the name starting at i (letters, digits, _; not starting with a digit), or i.
size_t name_end(std::string_view s, size_t i) {
  if (!(std::isalpha(static_cast<unsigned char>(s[i])) || s[i] == '_')) return i;
  size_t j = i;
  while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
  return j;
}

// A parameter's value: options.parameters, then options.shared_parameters; nullptr when neither has it.
const rational* parameter(const ParseOptions& options, const std::string& name) {
  if (auto it = options.parameters.find(name); it != options.parameters.end()) return &it->second;
  if (options.shared_parameters)
    if (auto it = options.shared_parameters->find(name); it != options.shared_parameters->end()) return &it->second;
  return nullptr;
}

// Whether the shared map holds T, s or z, whose checks depend on whether the expression names them:
// then the shared parameters are flattened (below) before parsing.
bool shared_needs_flattening(const ParseOptions& options) {
  const auto* shared = options.shared_parameters;
  return shared && (shared->count("T") || shared->count("s") || shared->count("z"));
}

// `options` with the shared parameters `text` names copied into `parameters` and the shared map
// dropped: what every check and use of `parameters` expects.
ParseOptions flattened(std::string_view text, const ParseOptions& options) {
  ParseOptions flat = options;
  flat.shared_parameters = nullptr;
  if (!options.shared_parameters) return flat;
  for (const auto& name : names_in(text))
    if (!flat.parameters.count(name))
      if (auto it = options.shared_parameters->find(name); it != options.shared_parameters->end()) flat.parameters.insert(*it);
  return flat;
}

// The factors of the denominators as written that the parse's operations cancelled and that have
// a root on or outside the stable region (their product; 1 when none), and the message naming the
// first operation that cancelled one.
struct Hidden {
  P factor{rational(1)};
  std::string what;
  bool beyond = false;  ///< their product would pass the model's degree limit (H as written is refused)
};

// A value while parsing: an exact rational function, or (ParsedExpression) the result of tape
// node `node` when it depends on a parameter whose value comes later.
struct Val {
  RF rf{P()};
  int node = -1;
  bool known() const { return node < 0; }
};

}  // namespace

/// The operations of a ParsedExpression that depend on its varying parameters, in the order the
/// parser met them (operands before the operation): replaying them repeats the parser's own
/// arithmetic and checks, so the result is the one a parse with those values gives.
struct ParsedExpression::Tape {
  enum class Op { name, add, sub, mul, div, neg, pow };
  struct Node {
    Op op;
    Val a, b;          ///< operands (a known value or an earlier node)
    std::string name;  ///< Op::name: the parameter
    int exponent = 0;  ///< Op::pow
    size_t token = 0;  ///< where the parser met it (its column in messages)
  };
  std::vector<Node> nodes;
  Val result;
  long known_bits = 0;  ///< the bits the known part spent (the parser's expansion limit counts them)
  Hidden known_hidden;  ///< the poles the known part cancelled
};

namespace {

class Parser {
 public:
  Parser(std::string_view text, const ParseOptions& opt, char var) : src_(text), opt_(opt), var_(var) {
    lex();
  }

  RF parse() { return parse_val().rf; }
  /// The poles on or outside the stable region that parse()'s operations cancelled (finish()).
  const Hidden& hidden() const { return hidden_; }

  /// The parse, with the parameters named in `varying` left open: their uses and every operation
  /// on them go to `tape` (the memo is not used: its groups hold values).
  void compile(const std::set<std::string>& varying, ParsedExpression::Tape& tape) {
    varying_ = &varying;
    tape_ = &tape;
    tape.result = parse_val();
    tape.known_bits = spent_bits_;
    tape.known_hidden = hidden_;
  }

  /// The tape's result at `values` (each varying parameter's), with the parser's checks; spent
  /// bits start at the known part's. InputError as the parser raises it.
  RF replay(const ParsedExpression::Tape& tape, const std::map<std::string, rational>& values, Hidden& hidden) const {
    using Op = ParsedExpression::Tape::Op;
    std::vector<RF> v(tape.nodes.size(), RF(P()));
    long spent = tape.known_bits;
    hidden = tape.known_hidden;
    auto get = [&](const Val& x) -> const RF& { return x.known() ? x.rf : v[size_t(x.node)]; };
    for (size_t k = 0; k < tape.nodes.size(); ++k) {
      const auto& n = tape.nodes[k];
      const Token& at = tokens_[n.token];
      switch (n.op) {
        case Op::name: v[k] = RF(P(values.at(n.name))); break;
        case Op::add:
        case Op::sub:
        case Op::mul: v[k] = combined(n.op, get(n.a), get(n.b), at, spent, hidden); break;
        case Op::div:
          if (get(n.b).num().is_zero()) fail(at, "division by zero");
          v[k] = combined(n.op, get(n.a), get(n.b), at, spent, hidden);
          break;
        case Op::neg: v[k] = -get(n.a); break;
        case Op::pow: v[k] = checked_power(get(n.a), n.exponent, at, spent); break;
      }
    }
    return get(tape.result);
  }
  bool used_T() const { return used_T_; }

 private:
  std::string_view src_;
  const ParseOptions& opt_;
  char var_;
  std::vector<Token> tokens_;
  std::vector<size_t> close_;  // for each '(' token, the index of its ')' (npos when unmatched)
  size_t pos_ = 0;
  int depth_ = 0;
  int deepest_ = 0;  // the deepest depth_ reached (a group's depth, for the memo)
  long spent_bits_ = 0;
  bool used_T_ = false;
  Hidden hidden_;
  const std::set<std::string>* varying_ = nullptr;  // compile(): the parameters left open
  ParsedExpression::Tape* tape_ = nullptr;

  Val parse_val() {
    if (tokens_.size() == 1) fail(tokens_[0], "the expression is empty");
    Val r = expr();
    if (peek().kind != Tok::end) {
      if (peek().kind == Tok::rparen) fail(peek(), "unmatched ')'");
      fail(peek(), "expected an operator (+ - * / ^) or the end of the expression, found " + describe(peek()));
    }
    return r;
  }

  // An operation on a value that depends on an open parameter: a tape node.
  Val node(ParsedExpression::Tape::Op op, Val a, Val b, const Token& at, int exponent = 0, std::string name = "") {
    const size_t token = size_t(&at - tokens_.data());
    tape_->nodes.push_back({op, std::move(a), std::move(b), std::move(name), exponent, token});
    Val r;
    r.node = int(tape_->nodes.size()) - 1;
    return r;
  }
  static Val known(RF r) {
    Val v;
    v.rf = std::move(r);
    return v;
  }

  std::string message(const Token& at, const std::string& what) const {
    std::ostringstream os;
    os << "expression '" << excerpt(src_, at.column) << "', column " << at.column << ": " << what;
    return os.str();
  }
  [[noreturn]] void fail(const Token& at, const std::string& what) const { throw InputError(message(at, what)); }

  // Size of every intermediate result (numeric/limits.hpp): its degree, its bits (all the
  // coefficients of numerator and denominator), and the bits the expression has produced so far.
  static long bits(const rational& c) {
    const auto* q = c.backend().data();
    return long(mpz_sizeinbase(mpq_numref(q), 2) + mpz_sizeinbase(mpq_denref(q), 2));
  }
  static long max_bits(const P& p) {
    long b = 0;
    for (const auto& c : p.coeffs()) b = std::max(b, bits(c));
    return b;
  }
  static long size_bits(const RF& r) {
    long b = 0;
    for (const auto* p : {&r.num(), &r.den()})
      for (const auto& c : p->coeffs()) b += bits(c);
    return b;
  }
  static int max_degree(const RF& r) { return std::max(r.num().degree(), r.den().degree()); }
  // An upper bound on the bits of p^k, known before it is computed: at most
  // min(k deg p + 1, C(k + t - 1, t - 1)) terms for t nonzero terms (the monomials of a
  // multinomial), each at most k (bits + log2 t + 1) bits. Saturates at 2^62.
  static long predicted_power_bits(const P& p, long k) {
    const long t = long(p.nonzero_terms());
    if (t == 0) return 0;
    long terms = 1;
    for (long i = 1; i < t && terms <= long(limits::intermediate_degree) + 1; ++i)  // C(k+t-1, t-1), capped
      terms = terms > (1L << 40) / (k + i) ? (1L << 40) : terms * (k + i) / i;
    terms = std::min(terms, long(p.degree()) * k + 1);
    long log_t = 1;
    while ((1L << log_t) < t) ++log_t;
    const long per_term = k * (max_bits(p) + log_t + 1);
    return per_term > (1L << 62) / terms ? (1L << 62) : terms * per_term;
  }
  RF checked(RF r, const Token& at, long& spent) const {
    if (max_degree(r) > limits::intermediate_degree)
      fail(at, "the result has degree " + std::to_string(max_degree(r)) + ", more than the limit of " +
                   std::to_string(limits::intermediate_degree));
    const long b = size_bits(r);
    if (b > limits::expression_bits)
      fail(at, "the result's exact coefficients take " + std::to_string(b) + " bits, more than the limit of " +
                   std::to_string(limits::expression_bits));
    spent += b;
    if (spent > limits::expansion_bits)
      fail(at, "expanding the expression up to here has produced " + std::to_string(spent) +
                   " bits of exact coefficients, more than the limit of " + std::to_string(limits::expansion_bits));
    return r;
  }
  RF checked(RF r, const Token& at) { return checked(std::move(r), at, spent_bits_); }

  // a + b, a - b, a b or a / b (b != 0), checked for size; a pole the operation cancels goes to
  // `hidden`. A pole the expression writes and the operation cancels -- (z - 2)/(z - 2),
  // 1/(z - 1) - 1/(z - 1), (z + 1)/(z - 1) * (z - 1) -- stays, realised as written, a hidden mode of
  // H: the factor lost is the written denominator (a.den b.den for a product, a.den b.num for a
  // quotient, lcm(a.den, b.den) for a sum: a pole both terms write is one mode) over the result's.
  // Inside the stable region (|z| < 1, Re s < 0) it changes no verdict and is dropped; the rest is
  // kept, with the message that names the first such operation (finish() decides). A product or
  // quotient that is 0 has no modes: a gain B = 0 removes its branch.
  RF combined(ParsedExpression::Tape::Op op, const RF& a, const RF& b, const Token& at, long& spent, Hidden& hidden) const {
    using Op = ParsedExpression::Tape::Op;
    RF r = checked(op == Op::add ? a + b : op == Op::sub ? a - b : op == Op::mul ? a * b : a / b, at, spent);
    const bool sum = op == Op::add || op == Op::sub;
    if (!sum && r.is_zero()) return r;
    const P& right = op == Op::div ? b.num() : b.den();
    if (r.den().degree() == a.den().degree() + right.degree()) return r;  // the result's denominator is the written one
    P natural;
    if (sum) {
      natural = a.den() == b.den() ? a.den() : divmod(a.den() * b.den(), gcd(a.den(), b.den())).first;
      if (r.den().degree() == natural.degree()) return r;
    } else {
      natural = a.den() * right;
    }
    const P lost = unstable_cancelled_factor(natural, r.den(), var_ == 'z' ? Domain::z : Domain::s);
    if (lost.is_zero()) return r;
    if (hidden.factor.degree() == 0)
      hidden.what = message(at, "the operation cancels " + to_string(lost, std::string(1, var_)) + ", a pole " +
                                    (var_ == 'z' ? "on or outside the unit circle" : "in Re s >= 0") +
                                    " that the expression writes: realised as written it stays a hidden mode, and hapstab "
                                    "does not reduce it away (write the expression without it if the reduced model is meant)");
    if (hidden.factor.degree() > 0 && opt_.hidden_poles == HiddenPoles::refuse) return r;  // the first one decides
    if (hidden.factor.degree() + lost.degree() > limits::model_degree) hidden.beyond = true;
    else hidden.factor = hidden.factor * lost;
    return r;
  }

  // base^n after the checks of its size, known before it is computed (refused before it fills memory)
  RF checked_power(const RF& base, int n, const Token& caret, long& spent) const {
    if (n < 0 && base.num().is_zero()) fail(caret, "division by zero (zero raised to a negative power)");
    const long k = std::abs(n);
    if (long(max_degree(base)) * k > limits::intermediate_degree)
      fail(caret, "the power has degree " + std::to_string(long(max_degree(base)) * k) + ", more than the limit of " +
                      std::to_string(limits::intermediate_degree));
    const long predicted = predicted_power_bits(base.num(), k) + predicted_power_bits(base.den(), k);
    if (predicted > limits::expression_bits)
      fail(caret, "the power's exact coefficients could take up to " + std::to_string(predicted) +
                      " bits, more than the limit of " + std::to_string(limits::expression_bits));
    return checked(base.pow(n), caret, spent);
  }

  // The character at byte i as a reader can see it: a UTF-8 sequence whole ('٣', not its first byte), a
  // control byte by its code (byte 0x1c).
  static std::string shown_character(std::string_view src, size_t i) {
    const auto b = static_cast<unsigned char>(src[i]);
    if (b < 0x20 || b == 0x7f) {
      char code[16];
      std::snprintf(code, sizeof code, "byte 0x%02x", b);
      return code;
    }
    size_t j = i + 1;
    if (b >= 0x80)
      while (j < src.size() && j < i + 4 && (static_cast<unsigned char>(src[j]) & 0xc0) == 0x80) ++j;
    return "'" + std::string(src.substr(i, j - i)) + "'";
  }

  void lex() {
    size_t i = 0;
    while (i < src_.size()) {
      char c = src_[i];
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
        continue;
      }
      size_t col = i + 1;
      if (const size_t j = number_end(src_, i); j > i) {
        tokens_.push_back({Tok::number, std::string(src_.substr(i, j - i)), col});
        i = j;
        continue;
      }
      if (const size_t j = name_end(src_, i); j > i) {
        tokens_.push_back({Tok::name, std::string(src_.substr(i, j - i)), col});
        i = j;
        continue;
      }
      Tok k;
      switch (c) {
        case '+': k = Tok::plus; break;
        case '-': k = Tok::minus; break;
        case '*': k = Tok::star; break;
        case '/': k = Tok::slash; break;
        case '^': k = Tok::caret; break;
        case '(': k = Tok::lparen; break;
        case ')': k = Tok::rparen; break;
        default:
          fail({Tok::end, "", col}, "unexpected character " + shown_character(src_, i) +
                                        " (allowed: numbers, names, + - * / ^ and parentheses)");
      }
      tokens_.push_back({k, std::string(1, c), col});
      ++i;
    }
    tokens_.push_back({Tok::end, "", src_.size() + 1});
    close_.assign(tokens_.size(), std::string::npos);
    std::vector<size_t> open;
    for (size_t k = 0; k < tokens_.size(); ++k)
      if (tokens_[k].kind == Tok::lparen) {
        open.push_back(k);
      } else if (tokens_[k].kind == Tok::rparen && !open.empty()) {
        close_[open.back()] = k;
        open.pop_back();
      }
  }

  // ParseMemo: a stored group stands in for parsing it again when the names it uses have the
  // values it was parsed with and the limits admit it as they did (so the outcome is the same).
  bool admits(const ParseMemo::Group& g) const {
    if (depth_ + g.depth > limits::nesting_depth || spent_bits_ + g.bits > limits::expansion_bits) return false;
    if (g.used_T && opt_.T != g.T) return false;
    for (const auto& [name, value] : g.parameters) {
      const rational* v = parameter(opt_, name);
      if (!v || *v != value) return false;
    }
    return true;
  }
  void remember(std::string key, size_t open, size_t close, const RF& value, long bits, int depth) {
    ParseMemo::Group g{value, {}, false, rational(0), bits, depth};
    std::set<std::string> seen;
    for (size_t k = open + 1; k < close; ++k) {
      const Token& t = tokens_[k];
      if (t.kind != Tok::name || (t.text.size() == 1 && t.text[0] == var_) || !seen.insert(t.text).second) continue;
      if (const rational* v = parameter(opt_, t.text)) {
        g.parameters.emplace_back(t.text, *v);
      } else if (t.text == "T") {
        g.used_T = true;
        g.T = opt_.T;
      }
    }
    opt_.memo->add(std::move(key), std::move(g));
  }

  const Token& peek() const { return tokens_[pos_]; }
  const Token& next() { return tokens_[pos_++]; }

  // expr := term (('+'|'-') term)*
  Val expr() {
    Val r = term();
    while (peek().kind == Tok::plus || peek().kind == Tok::minus) {
      const Token& op = next();
      Val t = term();
      const bool plus = op.kind == Tok::plus;
      const auto o = plus ? ParsedExpression::Tape::Op::add : ParsedExpression::Tape::Op::sub;
      if (r.known() && t.known()) r = known(combined(o, r.rf, t.rf, op, spent_bits_, hidden_));
      else r = node(o, std::move(r), std::move(t), op);
    }
    return r;
  }

  // term := unary (('*'|'/') unary)*
  Val term() {
    Val r = unary();
    while (peek().kind == Tok::star || peek().kind == Tok::slash) {
      const Token& op = next();
      Val f = unary();
      if (op.kind == Tok::star) {
        if (r.known() && f.known()) r = known(combined(ParsedExpression::Tape::Op::mul, r.rf, f.rf, op, spent_bits_, hidden_));
        else r = node(ParsedExpression::Tape::Op::mul, std::move(r), std::move(f), op);
      } else {
        if (f.known() && f.rf.num().is_zero()) fail(op, "division by zero");
        if (r.known() && f.known()) r = known(combined(ParsedExpression::Tape::Op::div, r.rf, f.rf, op, spent_bits_, hidden_));
        else r = node(ParsedExpression::Tape::Op::div, std::move(r), std::move(f), op);
      }
    }
    return r;
  }

  // unary := ('+'|'-')* power   (a loop, not recursion: "------z" cannot exhaust the stack)
  Val unary() {
    bool negate = false;
    const Token& first = peek();
    while (peek().kind == Tok::minus || peek().kind == Tok::plus) negate ^= next().kind == Tok::minus;
    Val r = power();
    if (!negate) return r;
    if (r.known()) return known(-r.rf);
    return node(ParsedExpression::Tape::Op::neg, std::move(r), Val{}, first);
  }

  // power := primary ('^' exponent)?   exponent := [+-]? integer | '(' [+-]? integer ')'
  Val power() {
    Val base = primary();
    if (peek().kind != Tok::caret) return base;
    const Token& caret = next();
    bool paren = false;
    if (peek().kind == Tok::lparen) {
      paren = true;
      next();
    }
    int sign = 1;
    if (peek().kind == Tok::minus || peek().kind == Tok::plus) sign = next().kind == Tok::minus ? -1 : 1;
    const Token& e = peek();
    bool integer_literal = e.kind == Tok::number && e.text.find_first_not_of("0123456789") == std::string::npos;
    if (!integer_literal) fail(e, "expected an integer exponent after '^' at column " + std::to_string(caret.column) +
                                      ", found " + describe(e));
    next();
    if (e.text.size() > 4) fail(e, "exponent " + e.text + " is too large (at most 9999)");
    int n = sign * std::stoi(e.text);
    if (paren) {
      if (peek().kind != Tok::rparen) fail(peek(), "expected ')' to close the exponent, found " + describe(peek()));
      next();
    }
    if (n < 0 && base.known() && base.rf.num().is_zero())
      fail(caret, "division by zero (zero raised to a negative power)");
    if (peek().kind == Tok::caret) fail(peek(), "write (a^b)^c with parentheses: a^b^c is ambiguous");
    if (!base.known()) return node(ParsedExpression::Tape::Op::pow, std::move(base), Val{}, caret, n);
    return known(checked_power(base.rf, n, caret, spent_bits_));
  }

  // primary := number | name | '(' expr ')'
  Val primary() {
    const Token& t = peek();
    switch (t.kind) {
      case Tok::number: {
        next();
        auto q = try_parse_rational(t.text);
        if (!q) fail(t, "malformed number '" + t.text + "'");
        return known(RF(P(*q)));
      }
      case Tok::name: {
        next();
        if (t.text.size() == 1 && t.text[0] == var_) return known(RF(P::monomial(1, rational(1))));
        if (varying_ && varying_->count(t.text)) return node(ParsedExpression::Tape::Op::name, Val{}, Val{}, t, 0, t.text);
        if (const rational* v = parameter(opt_, t.text)) return known(RF(P(*v)));
        if (t.text == "T") {
          if (opt_.T <= 0) fail(t, "the expression uses T but no sample period was given (" + opt_.period_hint + ")");
          used_T_ = true;
          return known(RF(P(opt_.T)));
        }
        if ((t.text == "z" || t.text == "s") && t.text[0] != var_)
          fail(t, std::string("the expression mixes the variables s and z (this one is in ") + var_ + ")");
        std::string known = std::string(1, var_) + ", T";
        for (const auto& [k, v] : opt_.parameters) known += ", " + k;
        if (opt_.shared_parameters)  // the shared ones this expression names (all of them could be a thousand)
          for (const auto& k : names_in(src_))
            if (!opt_.parameters.count(k) && opt_.shared_parameters->count(k)) known += ", " + k;
        std::string hint = opt_.parameter_hint;
        if (const size_t at = hint.find("{}"); at != std::string::npos) hint.replace(at, 2, t.text);
        fail(t, "unknown name '" + t.text + "' (known: " + known + "; " + hint + ")");
      }
      case Tok::lparen: {
        const size_t open = pos_, close = close_[pos_];
        next();
        if (peek().kind == Tok::rparen) fail(peek(), "empty parentheses");
        const bool memoise = opt_.memo && !varying_ && close != std::string::npos && close - open - 1 >= ParseMemo::kMinTokens;
        std::string key;
        if (memoise) {
          key = var_ + std::string(src_.substr(t.column - 1, tokens_[close].column - t.column + 1));
          if (const ParseMemo::Group* g = opt_.memo->find(key); g && admits(*g)) {
            pos_ = close + 1;
            spent_bits_ += g->bits;
            used_T_ = used_T_ || g->used_T;
            deepest_ = std::max(deepest_, depth_ + g->depth);
            return known(g->value);
          }
        }
        const long bits0 = spent_bits_;
        const int depth0 = depth_, deepest0 = deepest_, hidden0 = hidden_.factor.degree();
        deepest_ = depth_;
        if (++depth_ > limits::nesting_depth)
          fail(t, "parentheses nested deeper than " + std::to_string(limits::nesting_depth) + " levels, the limit");
        deepest_ = std::max(deepest_, depth_);
        Val r = expr();
        --depth_;
        if (peek().kind != Tok::rparen)
          fail(peek(), "expected ')' to close '(' at column " + std::to_string(t.column) + ", found " + describe(peek()));
        next();
        // a group that cancels a pole is parsed each time (its message names its own column)
        if (memoise && hidden_.factor.degree() == hidden0)
          remember(std::move(key), open, close, r.rf, spent_bits_ - bits0, deepest_ - depth0);
        deepest_ = std::max(deepest_, deepest0);
        return r;
      }
      case Tok::end: fail(t, "the expression ends where a number, a name or '(' was expected");
      default: fail(t, "expected a number, a name or '(', found " + describe(t));
    }
  }
};

char infer_variable(std::string_view text, const ParseOptions& opt) {
  if (opt.variable == 'z' || opt.variable == 's') return opt.variable;
  if (opt.variable != 0) throw InputError(std::string("variable must be 'z' or 's', got '") + opt.variable + "'");
  bool has_z = false, has_s = false;
  for (size_t i = 0; i < text.size(); ++i) {
    if (!std::isalpha(static_cast<unsigned char>(text[i]))) continue;
    size_t j = i;
    while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
    auto name = text.substr(i, j - i);
    bool after_digit = i > 0 && (std::isdigit(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.');
    if (!after_digit || (name != "e" && name != "E")) {
      if (name == "z" && !parameter(opt, "z")) has_z = true;
      if (name == "s" && !parameter(opt, "s")) has_s = true;
    }
    i = j - 1;
  }
  if (has_z && has_s) throw InputError("expression '" + excerpt(text, 1) + "' mixes the variables s and z");
  if (has_z) return 'z';
  if (has_s) return 's';
  return opt.T > 0 ? 'z' : 's';
}

}  // namespace

const ParseMemo::Group* ParseMemo::find(const std::string& key) const {
  auto it = groups_.find(key);
  return it == groups_.end() ? nullptr : &it->second;
}

void ParseMemo::add(std::string key, Group g) {
  // the text, the coefficients (at most the bits the parse expanded) and the named values
  const size_t bytes = key.size() + static_cast<size_t>(g.bits / 8) + 64 * (g.parameters.size() + 1);
  if (used_bytes_ + bytes > kBudgetBytes) return;
  used_bytes_ += bytes;
  groups_.emplace(std::move(key), std::move(g));
}

std::set<std::string> names_in(std::string_view text) {
  std::set<std::string> names;
  for (size_t i = 0; i < text.size();) {
    if (size_t j = number_end(text, i); j > i) {
      i = j;
    } else if (j = name_end(text, i); j > i) {
      names.emplace(text.substr(i, j - i));
      i = j;
    } else {
      ++i;
    }
  }
  return names;
}

namespace {

// parse_tf's checks of the options and the text, before parsing; returns the variable.
char check_input(std::string_view text, const ParseOptions& options) {
  if (options.T < 0) throw InputError("sample period T must be > 0, got " + to_decimal(options.T, 17));
  for (const auto& [k, v] : options.parameters) {
    if (k.empty() || !(std::isalpha(static_cast<unsigned char>(k[0])) || k[0] == '_'))
      throw InputError("parameter name '" + k + "' must start with a letter");
    if (k == "T") throw InputError("parameter 'T' is the sample period: give it with --T, not --set");
  }
  if (text.size() > limits::expression_chars)
    throw InputError("expression '" + excerpt(text, 1) + "': " + std::to_string(text.size()) +
                     " characters, more than the limit of " + std::to_string(limits::expression_chars));
  char var = infer_variable(text, options);
  if (options.parameters.count(std::string(1, var)))
    throw InputError(std::string("parameter '") + var + "' clashes with the variable " + var);
  return var;
}

// parse_tf's end: the poles the operations cancelled (ParseOptions::hidden_poles), the model's
// degree limit and the domain.
TransferFunction finish(RF H, const Hidden& hidden, std::string_view text, const ParseOptions& options, char var) {
  if (hidden.factor.degree() > 0) {
    const bool allowed = hidden.beyond ? false
                         : options.hidden_poles == HiddenPoles::allow_marginal
                             ? var == 'z' && marginally_stable(H.den() * hidden.factor)
                             : options.hidden_poles == HiddenPoles::allow_integrator && var == 's' &&
                                   hidden.factor == P::monomial(1, rational(1));
    if (!allowed) throw InputError(hidden.what);
  }
  const int degree = std::max(H.num().degree(), H.den().degree());
  if (degree > limits::model_degree)
    throw InputError("expression '" + excerpt(text, 1) + "' has degree " + std::to_string(degree) +
                     ", more than the limit of " + std::to_string(limits::model_degree) + " for a model");
  TransferFunction out;
  out.H = std::move(H);
  out.domain = var == 'z' ? Domain::z : Domain::s;
  if (out.domain == Domain::z) {
    if (options.T <= 0)
      throw InputError("expression '" + excerpt(text, 1) + "' is in z: a sample period T > 0 is required (--T)");
    out.T = options.T;
  } else {
    out.T = 0;
  }
  return out;
}

}  // namespace

TransferFunction parse_tf(std::string_view text, const ParseOptions& options) {
  if (shared_needs_flattening(options)) return parse_tf(text, flattened(text, options));
  const char var = check_input(text, options);
  Parser p(text, options, var);
  RF H = p.parse();
  return finish(std::move(H), p.hidden(), text, options, var);
}

// ---- ParsedExpression ---------------------------------------------------------------------------

struct ParsedExpression::State {
  std::string text;
  ParseOptions options;  ///< with the varying parameters at 0 (their names count, not their values)
  std::set<std::string> varying;
  char var = 0;
  std::unique_ptr<Parser> parser;  ///< holds the tokens; refers to text and options (owned here)
  Tape tape;
};

ParsedExpression::ParsedExpression(std::string_view text, const ParseOptions& options, std::set<std::string> varying)
    : state_() {
  auto state = std::make_shared<State>();
  State& s = *state;
  s.text = std::string(text);
  s.options = flattened(text, options);
  s.options.memo = nullptr;
  for (const auto& name : varying) s.options.parameters.emplace(name, rational(0));
  s.varying = std::move(varying);
  s.var = check_input(s.text, s.options);
  s.parser = std::make_unique<Parser>(s.text, s.options, s.var);
  s.parser->compile(s.varying, s.tape);
  state_ = std::move(state);
}

ParsedExpression::~ParsedExpression() = default;

size_t ParsedExpression::operations() const { return state_->tape.nodes.size(); }

std::pair<long, long> ParsedExpression::degree_bound() const {
  using Op = Tape::Op;
  const Tape& t = state_->tape;
  auto sat = [](long x) { return std::min<long>(x, 1000000); };
  std::vector<std::pair<long, long>> d(t.nodes.size(), {0, 0});
  auto get = [&](const Val& x) { return x.known() ? std::pair<long, long>{0, 0} : d[size_t(x.node)]; };
  for (size_t k = 0; k < t.nodes.size(); ++k) {
    const auto& n = t.nodes[k];
    const auto [na, da] = get(n.a);
    const auto [nb, db] = get(n.b);
    switch (n.op) {
      case Op::name: d[k] = {1, 0}; break;
      case Op::add:
      case Op::sub: d[k] = {sat(std::max(na + db, nb + da)), sat(da + db)}; break;
      case Op::mul: d[k] = {sat(na + nb), sat(da + db)}; break;
      case Op::div: d[k] = {sat(na + db), sat(da + nb)}; break;
      case Op::neg: d[k] = {na, da}; break;
      case Op::pow: {
        const long e = std::abs(static_cast<long>(n.exponent));
        d[k] = n.exponent >= 0 ? std::pair<long, long>{sat(e * na), sat(e * da)} : std::pair<long, long>{sat(e * da), sat(e * na)};
        break;
      }
    }
  }
  return get(t.result);
}

TransferFunction ParsedExpression::at(const std::map<std::string, rational>& values) const {
  const State& s = *state_;
  for (const auto& name : s.varying)
    if (!values.count(name)) throw std::logic_error("ParsedExpression::at: no value for '" + name + "'");
  try {
    Hidden hidden;
    RF H = s.parser->replay(s.tape, values, hidden);
    return finish(std::move(H), hidden, s.text, s.options, s.var);
  } catch (const InputError&) {
    // the parser's own outcome at these values, error and message as parse_tf gives them
    ParseOptions o = s.options;
    for (const auto& [k, v] : values) o.parameters[k] = v;
    return parse_tf(s.text, o);
  }
}

AffineSplit split_affine(std::string_view text, const ParseOptions& options, const std::string& name) {
  ParseOptions po = flattened(text, options);
  po.parameters.erase(name);
  const auto [dn, dd] = ParsedExpression(text, po, {name}).degree_bound();
  const long D = std::max(dn, dd + 1);  // the degree in K of the numerator of H - H0 - K H1
  constexpr long kMaxDegree = 64;
  if (D > kMaxDegree)
    throw InputError("the expression must be affine in " + name + ", and its degree in " + name + " is bounded only by " +
                     std::to_string(D) + " (more than " + std::to_string(kMaxDegree) +
                     " values would be needed to prove it affine); write it as H0 + " + name + " H1");
  auto at = [&](const rational& k) {
    po.parameters[name] = k;
    return parse_tf(text, po);
  };
  AffineSplit s{at(0), at(1)};
  const RationalFunction<rational> H1 = s.H1.H - s.H0.H;
  if (H1.is_zero()) throw InputError("the expression does not depend on " + name);
  s.H1.H = H1;
  // D - 1 more values where the expression is defined: with K = 0 and 1, D + 1 roots of a
  // polynomial of degree <= D in K, so it is 0 and H = H0 + K H1 for every K (the degree bound
  // also bounds how many values can divide by zero: at most dd of them)
  long proven = 2, tried = 0;
  for (long j = 2; proven < D + 1; ++j) {
    const rational k = j % 2 == 0 ? rational(j, 3) : rational(-j, 7);  // distinct, never 0 or 1
    ++tried;
    try {
      if (at(k).H != s.H0.H + RationalFunction<rational>(k) * H1)
        throw InputError("the expression must be affine in " + name + " (H = H0 + " + name + " H1, e.g. a stiffness or a damping)");
    } catch (const InputError& e) {
      const std::string what = e.what();
      const bool pole_at_k = what.find("division by zero") != std::string::npos || what.find("the operation cancels") != std::string::npos;
      if (!pole_at_k || tried > D + dd + 2) throw;
      continue;  // a pole of the expression at this k (or one it cancels there): another value
    }
    ++proven;
  }
  return s;
}

}  // namespace hapstab
