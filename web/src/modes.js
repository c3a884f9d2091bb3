// Syntax colouring of the four post dialects, as CodeMirror stream
// languages: colouring only (what a post means is the Rust side's).
import { StreamLanguage } from "@codemirror/language";
import { javascript } from "@codemirror/legacy-modes/mode/javascript";

// Vectric .pp: `+` comments, quoted output lines with [LABELS], keywords.
const vectric = {
  name: "vectric",
  startState: () => ({ inString: false }),
  token(stream, state) {
    if (state.inString) {
      if (stream.match(/^\[[A-Za-z_0-9]+\]?/)) return "variableName.special";
      if (stream.skipTo('"') || stream.skipTo("[")) {
        if (stream.peek() === '"') { stream.next(); state.inString = false; }
        return "string";
      }
      stream.skipToEnd();
      state.inString = false;
      return "string";
    }
    if (stream.sol() && stream.match(/^\s*\+/)) { stream.skipToEnd(); return "comment"; }
    if (stream.eatSpace()) return null;
    if (stream.peek() === '"') { stream.next(); state.inString = true; return "string"; }
    if (stream.match(/^begin\b/i)) return "keyword";
    if (stream.match(/^[A-Z_][A-Z_0-9]*(?=\s*=)/)) return "propertyName";
    if (stream.match(/^(VAR|IF|ELSE|ENDIF)\b/)) return "keyword";
    if (stream.match(/^[A-Z_][A-Z_0-9]*\b/)) return "typeName";
    if (stream.match(/^-?\d+(\.\d*)?/)) return "number";
    stream.next();
    return null;
  },
};

// Vericut VcPost: BASIC-like; `'` and `Rem` comments.
const VCPOST_KEYWORDS = /^(sub|end|if|then|else|elseif|endif|for|to|next|while|wend|do|loop|dim|call|out|select|case|and|or|not|function|return|exit)\b/i;
const vcpost = {
  name: "vcpost",
  token(stream) {
    if (stream.eatSpace()) return null;
    if (stream.match(/^'/) || stream.match(/^rem\b/i)) { stream.skipToEnd(); return "comment"; }
    if (stream.match(/^"([^"]|"")*"?/)) return "string";
    if (stream.match(VCPOST_KEYWORDS)) return "keyword";
    if (stream.match(/^-?\d+(\.\d*)?/)) return "number";
    if (stream.match(/^[A-Za-z_][A-Za-z_0-9.]*/)) return "variableName";
    stream.next();
    return null;
  },
};

// The IR as RON: comments, strings, numbers, field names.
const ron = {
  name: "ron",
  token(stream) {
    if (stream.eatSpace()) return null;
    if (stream.match("//")) { stream.skipToEnd(); return "comment"; }
    if (stream.match(/^"([^"\\]|\\.)*"?/)) return "string";
    if (stream.match(/^-?\d+(\.\d*)?([eE][-+]?\d+)?/)) return "number";
    if (stream.match(/^[a-z_][a-z_0-9]*(?=\s*:)/)) return "propertyName";
    if (stream.match(/^[A-Z][A-Za-z0-9_]*/)) return "typeName";
    stream.next();
    return null;
  },
};

/** The colouring for a file name's extension. */
export function languageFor(path) {
  const ext = (path.split(".").pop() || "").toLowerCase();
  switch (ext) {
    case "pp": return StreamLanguage.define(vectric);
    case "js": case "cps": return StreamLanguage.define(javascript);
    case "vcpost": return StreamLanguage.define(vcpost);
    case "ron": return StreamLanguage.define(ron);
    default: return [];
  }
}
