"""Serves build/web on localhost with the headers that let the page use threads (cross-origin isolation)."""
import functools
import http.server
import sys


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, '.wasm': 'application/wasm',
                      '.js': 'text/javascript'}

    def end_headers(self):
        self.send_header('Cross-Origin-Opener-Policy', 'same-origin')
        self.send_header('Cross-Origin-Embedder-Policy', 'require-corp')
        self.send_header('Cache-Control', 'no-cache')
        super().end_headers()

    def log_message(self, *args):
        pass


def main():
    folder, port = sys.argv[1], int(sys.argv[2])
    server = http.server.ThreadingHTTPServer(('127.0.0.1', port),
                                             functools.partial(Handler, directory=folder))
    print(f'Nome in the browser: http://127.0.0.1:{port}/  (Ctrl+C stops)', flush=True)
    server.serve_forever()


if __name__ == '__main__':
    main()
