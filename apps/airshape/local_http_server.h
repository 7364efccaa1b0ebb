#pragma once

#include <optional>
#include <string>

namespace airshape::cli {

/// A minimal HTTP/1.0 server for one local user: it listens on 127.0.0.1 only and answers one
/// request per connection, in turn (what `airshape view` serves is small and local).
class LocalHttpServer {
 public:
  struct Request {
    std::string method;  ///< "GET", "POST", ...
    std::string path;    ///< without the query
    std::string query;   ///< after '?', as sent
  };

  /// The value of a query parameter (percent-decoded), if the query has it.
  static std::optional<std::string> parameter(const std::string& query, const std::string& name);
  struct Response {
    int status = 200;
    std::string contentType = "text/plain; charset=utf-8";
    std::string body;
  };

  /// Listens on 127.0.0.1:port (0: a free port). Throws Error when it cannot.
  explicit LocalHttpServer(int port);
  ~LocalHttpServer();
  LocalHttpServer(const LocalHttpServer&) = delete;
  LocalHttpServer& operator=(const LocalHttpServer&) = delete;

  int port() const { return port_; }

  /// Waits up to `milliseconds` for a request and reads it; nothing when none came (or the
  /// wait was interrupted by a signal). The request must be answered with respond().
  std::optional<Request> next(int milliseconds);
  /// Answers the request next() returned and closes its connection.
  void respond(const Response& response);

 private:
  int listening_ = -1;
  int connection_ = -1;
  int port_ = 0;
};

}  // namespace airshape::cli
