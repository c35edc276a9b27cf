"""A context manager that does its work on entry, every `every` seconds on a daemon thread
while the block runs, and once more on exit: what the runner's progress line and a launch's
cost record both need."""
import threading


class Repeating:
    def __init__(self, every):
        self.every = every
        self._stop = threading.Event()
        self._thread = None

    def begin(self):
        """The work on entry (by default the same as every tick)."""
        self.tick()

    def tick(self):
        raise NotImplementedError

    def _loop(self):
        while not self._stop.wait(self.every):
            self.tick()

    def __enter__(self):
        self.begin()
        self._thread = threading.Thread(target=self._loop, daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc):
        self._stop.set()
        self._thread.join()
        self.tick()
        return False
