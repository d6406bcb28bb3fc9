"""The per-endpoint scheduler every HTTP backend shares: slots, endpoint choice and retries.

At most ``batch_size`` requests are in flight per endpoint (a server queues silently beyond its
parallel slots, then answers 503); code requests go before selections; transient failures —
connection errors, timeouts, 408/429/5xx (529 included) — are retried with exponential backoff or after the
server's Retry-After; other 4xx errors (unknown model, unsupported option) are permanent. An
endpoint that keeps failing is taken out for a while.

A server that stops answering (every request times out or finds no connection) must not hold a
run for hours: after ``SILENT_AFTER`` requests in a row got no answer at all, requests for it are
refused at once without being sent, except one at a time, after a pause, that checks whether it
answers again. A run against a hung server thus ends in about two request timeouts, its tasks lost
(and done by ``--resume``), whatever its number of tasks. Any HTTP answer, even an error, shows the
server is alive: a busy server (429, 503) is retried as before, never refused.
"""

from __future__ import annotations

import asyncio
import heapq
import time
from dataclasses import dataclass, replace
from typing import Any

from tenacity import AsyncRetrying, RetryCallState, retry_if_exception, stop_after_attempt, wait_exponential

from meceng.llm.types import ChatRequest, ChatResponse, LLMError, LLMSettings
from meceng.logs import get_logger

log = get_logger(__name__)

# 529: Anthropic's "overloaded"
TRANSIENT_STATUS = frozenset({408, 425, 429, 500, 502, 503, 504, 529})
SILENT_AFTER = 3  # requests in a row without any answer before the endpoint's requests are refused unsent
# how long an idle connection stays open: between two requests of a slot (an answer parsed, the next
# prompt built) a connection idles a few ms to seconds; closing it would cost a new TCP handshake
KEEPALIVE_S = 60.0


class PrioritySlots:
    """A semaphore that serves waiters by priority, then arrival.

    Code-generation requests (priority 0) of tasks that already chose their components go before
    selection requests (priority 1) of new tasks: tasks finish depth-first, so their evaluation
    overlaps the remaining inference instead of waiting for every selection to be done. When
    several runs of a sweep share a server's slots, ``rank`` (the run's place in the sweep) comes
    first: an earlier run is served first and a later one fills only the slots it leaves free.
    """

    def __init__(self, capacity: int) -> None:
        self.capacity = capacity
        self.free = capacity
        self._waiters: list[tuple[int, int, int, asyncio.Future[None]]] = []
        self._seq = 0

    @property
    def waiting(self) -> int:
        return len(self._waiters)

    async def acquire(self, priority: int, rank: int = 0) -> None:
        if self.free > 0 and not self._waiters:
            self.free -= 1
            return
        future: asyncio.Future[None] = asyncio.get_running_loop().create_future()
        self._seq += 1
        heapq.heappush(self._waiters, (rank, priority, self._seq, future))
        try:
            await future
        except asyncio.CancelledError:
            if future.done() and not future.cancelled():
                self.release()  # the slot was handed over just as we were cancelled
            else:
                self._waiters = [w for w in self._waiters if w[3] is not future]
                heapq.heapify(self._waiters)
            raise

    def release(self) -> None:
        while self._waiters:
            *_, future = heapq.heappop(self._waiters)
            if not future.done():
                future.set_result(None)  # hand the slot over directly
                return
        self.free += 1


PRIORITY = {"code": 0, "select": 1}


@dataclass
class Endpoint:
    host: str
    client: Any
    slots: PrioritySlots
    capacity: int
    in_flight: int = 0
    failures: int = 0
    disabled_until: float = 0.0
    silent: int = 0  # requests in a row that got no answer at all (timeout, no connection)
    probing: bool = False  # a request is checking whether a silent endpoint answers again

    @property
    def free(self) -> int:
        # the second term counts the other runs of a sweep on shared slots (equal when unshared)
        return min(self.capacity - self.in_flight, self.slots.free - self.slots.waiting)

    def admit(self, now: float) -> bool:
        """Whether a request may be sent: always while the server answers; once it fell silent,
        only one at a time after the pause (the others fail at once instead of waiting out a
        timeout each)."""
        if self.silent < SILENT_AFTER:
            return True
        if self.probing or now < self.disabled_until:
            return False
        self.probing = True
        return True


def _is_transient(exc: BaseException) -> bool:
    return isinstance(exc, LLMError) and exc.transient


class EndpointBackend:
    """A backend that sends each request to one of its hosts: subclasses say how (``_send``) and
    how an answer reads (``_convert``); the slots, endpoint choice and retries are here."""

    name = "endpoints"

    def __init__(self, settings: LLMSettings, client_factory: Any = None) -> None:
        """``client_factory(host, connections)`` makes a host's HTTP client with a pool of
        ``connections`` (idle ones kept alive): one per slot, so that no client pool caps the batch
        size (httpx's default pool of 100 kept a run at ``--batch-size 128`` at 100 in flight)."""
        self.settings = settings
        self._client_factory = client_factory
        capacity = max(1, settings.batch_size)
        self.endpoints = [
            Endpoint(host=h.rstrip("/"), client=client_factory(h, capacity) if client_factory else None,
                     slots=PrioritySlots(capacity), capacity=capacity)
            for h in settings.hosts
        ]
        self._pick_lock = asyncio.Lock()
        self.rank = 0

    def share_slots(self, servers: dict[str, PrioritySlots], rank: int) -> None:
        """Take each host's slots from ``servers`` (made here for a host not in it yet), so that the
        runs of a sweep that use one server never have more requests in flight than its slots;
        ``rank`` orders this backend's waiting requests against the other runs'."""
        for endpoint in self.endpoints:
            endpoint.slots = servers.setdefault(endpoint.host, PrioritySlots(endpoint.capacity))
            if endpoint.slots.capacity != endpoint.capacity and self._client_factory is not None:
                # still unused (no request yet): a pool the size of the shared slots instead
                endpoint.client = self._client_factory(endpoint.host, endpoint.slots.capacity)
            endpoint.capacity = endpoint.slots.capacity
        self.rank = rank

    async def chat(self, request: ChatRequest) -> ChatResponse:
        attempts = 0
        backoff = wait_exponential(multiplier=self.settings.backoff_s, max=60)

        def wait(state: RetryCallState) -> float:
            exc = state.outcome.exception() if state.outcome else None
            if isinstance(exc, LLMError) and exc.retry_after is not None:
                return min(exc.retry_after, 120.0)  # the server said when; believe it, within reason
            return backoff(state)

        retrying = AsyncRetrying(
            retry=retry_if_exception(_is_transient),
            stop=stop_after_attempt(self.settings.max_attempts),
            wait=wait,
            reraise=True,
        )
        async for attempt in retrying:
            with attempt:
                attempts += 1
                response = await self._chat_once(request)
                return _with_attempts(response, attempts)
        raise AssertionError("unreachable")  # pragma: no cover

    def _choose(self) -> Endpoint:
        now = time.monotonic()
        usable = [e for e in self.endpoints if e.disabled_until <= now] or self.endpoints
        return max(usable, key=lambda e: (e.free, -e.failures))

    async def _chat_once(self, request: ChatRequest) -> ChatResponse:
        async with self._pick_lock:
            endpoint = self._choose()
            endpoint.in_flight += 1
        await endpoint.slots.acquire(PRIORITY.get(request.purpose, 1), self.rank)
        try:  # the slot is held for exactly one request
            if not endpoint.admit(time.monotonic()):
                raise LLMError(f"{endpoint.host} gave no answer to {endpoint.silent} requests in a row: not sent",
                               transient=True)
            try:
                raw, wall = await self._send(endpoint, request)
            except LLMError as exc:
                if exc.status is not None:  # an HTTP answer, even an error: the server is alive
                    endpoint.silent = 0
                raise
            finally:
                endpoint.probing = False
        finally:
            endpoint.slots.release()
            endpoint.in_flight -= 1
        endpoint.failures = endpoint.silent = 0
        return self._convert(raw, wall, endpoint.host)

    def _convert(self, raw: Any, wall: float, host: str) -> ChatResponse:
        raise NotImplementedError

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        raise NotImplementedError

    def _note_silence(self, endpoint: Endpoint) -> None:
        """A request that got no answer at all (timeout, refused or dropped connection)."""
        endpoint.silent += 1
        self._note_failure(endpoint, True)

    def _note_failure(self, endpoint: Endpoint, transient: bool) -> None:
        if transient:
            endpoint.failures += 1
            if endpoint.failures >= 3:
                endpoint.disabled_until = time.monotonic() + min(60.0, 5.0 * endpoint.failures)
                log.warning("endpoint taken out", host=endpoint.host, failures=endpoint.failures)

    async def aclose(self) -> None:
        return None


def _with_attempts(response: ChatResponse, attempts: int) -> ChatResponse:
    if attempts == 1:
        return response
    return replace(response, attempts=attempts)
