// The pages' only way to the server. JSON in, JSON out; every failure becomes an
// ApiError, never an exception text or a stack trace on the page.
//
// Error bodies: {"detail": [{loc, msg, type}, …]} (the list shape: 400, 413, 422,
// and in time every status) or {"detail": "…"} (401, 403, 404, 409 today). Both
// give the same ApiError: ``fieldErrors`` holds the list's entries, ``detail`` the
// text to show (the string, or the list's messages joined).

export const API = "/api/v1";

/** A failed request: HTTP status (0 when the server was not reached) and what it said. */
export class ApiError extends Error {
  constructor({ status, fieldErrors = [], detail = null, kind = "http", lang = "en" }) {
    super(detail ?? (kind === "bad_response" ? `unexpected answer (HTTP ${status})` : `HTTP ${status}`));
    this.name = "ApiError";
    this.status = status;
    /** [{loc: [...], msg, type}] of a list-shaped error body */
    this.fieldErrors = fieldErrors;
    /** the server's words: a string detail, or the list's messages joined; else null */
    this.detail = detail;
    /** "http", "network" or "bad_response" */
    this.kind = kind;
    /** the language the server wrote its words in (its Content-Language) */
    this.lang = lang;
  }
}

/** The ApiError for a non-2xx answer with the (parsed, possibly null) body ``data``. */
export function errorFromBody(status, data, lang = "en") {
  const detail = data && typeof data === "object" ? data.detail : undefined;
  if (Array.isArray(detail)) {
    const fieldErrors = detail
      .filter((e) => e && typeof e === "object")
      .map((e) => ({
        loc: Array.isArray(e.loc) ? e.loc : [],
        msg: String(e.msg ?? ""),
        type: String(e.type ?? ""),
        code: String(e.code ?? e.type ?? ""),
        /** the language the server wrote ``msg`` in (its Content-Language) */
        lang,
      }));
    const text = fieldErrors.map((e) => e.msg).filter(Boolean).join("; ");
    return new ApiError({ status, fieldErrors, detail: text || null, lang });
  }
  if (typeof detail === "string") return new ApiError({ status, detail, lang });
  return new ApiError({ status });
}

/** The language of a successful answer's messages (its Content-Language), by its data. */
const answerLanguages = new WeakMap();

/**
 * The language the server wrote ``data``'s messages in (the answer's Content-Language,
 * "en" where it named none): the page marks those messages with it (``lang``).
 */
export function answerLanguage(data) {
  return (data !== null && typeof data === "object" && answerLanguages.get(data)) || "en";
}

/**
 * A client for JSON endpoints under ``base``.
 *
 * ``headers()`` gives headers for every request (the sales page's Bearer key, the
 * page's language as Accept-Language, so that the server's messages come in it);
 * ``onError(error)`` sees every ApiError before it is thrown (the sales page goes
 * back to its key prompt on a 401).
 */
export function createClient({ base = API, headers = () => ({}), onError = null } = {}) {
  /**
   * @param {string} method
   * @param {string} path
   * @param {{body?: unknown, headers?: Record<string, string>}} [options]
   */
  async function request(method, path, { body, headers: extra = {} } = {}) {
    const init = { method, headers: { Accept: "application/json", ...headers(), ...extra } };
    if (body !== undefined) {
      init.headers["Content-Type"] = "application/json";
      init.body = JSON.stringify(body);
    }
    const fail = (error) => {
      onError?.(error);
      return error;
    };
    let response;
    try {
      response = await fetch(`${base}${path}`, init);
    } catch {
      throw fail(new ApiError({ status: 0, kind: "network" }));
    }
    let data;
    try {
      const text = await response.text();
      data = text ? JSON.parse(text) : null;
    } catch {
      data = null;
    }
    const language = (response.headers.get("Content-Language") ?? "en").split(",")[0].trim() || "en";
    if (!response.ok) throw fail(errorFromBody(response.status, data, language));
    if (response.status === 204) return null;
    if (data === null || typeof data !== "object") {
      throw fail(new ApiError({ status: response.status, kind: "bad_response" }));
    }
    answerLanguages.set(data, language);
    return data;
  }
  return {
    request,
    get: (path, options) => request("GET", path, options),
    post: (path, body, options = {}) => request("POST", path, { ...options, body }),
  };
}

/** A path with every interpolated segment URI-encoded: ``encodePath`/quotes/${number}/status` ``. */
export function encodePath(strings, ...values) {
  return strings.reduce(
    (out, text, i) => out + text + (i < values.length ? encodeURIComponent(values[i]) : ""),
    "",
  );
}
