"""A real OpenAI-compatible server for the tests: llama.cpp's, through llama-cpp-python's
``python -m llama_cpp.server``, serving a tiny llama the tests write themselves.

No weights can be downloaded here, and none are needed: a 32-wide, one-layer llama with random
weights and a byte-level vocabulary reads a prompt in well under a second, and its answers are
noise (``#`` repeated), so every task it is given must end as the model's failure. What is real
is everything around the model: the HTTP server, its request validation, the chat template, its
tool-call handling, its context checks, its answer limits and its queue. Needs the ``servers``
extra (``pip install -e ".[dev,servers]"``).
"""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import httpx
import numpy as np

# 32 wide, one layer: a MecEng selection prompt (~5,600 byte tokens) is read in ~0.5 s on one core
# with flash attention (64 x 2 layers: ~2 s), and the suite sends dozens of them
EMBED = 32
LAYERS = 1
HEADS = 2
FFN = 64
TRAINED_CONTEXT = 16384  # a server context above the trained one breaks llama.cpp's decode (FIELD-NOTES)
SERVED_NAME = "tiny"

# a plain chat template without special tokens: the prompt is the conversation as text
CHAT_TEMPLATE = (
    "{% for message in messages %}"
    "{{ message['role'] }}: {{ message['content'] or '' }}\n"
    "{% endfor %}"
    "{% if add_generation_prompt %}assistant: {% endif %}"
)


def servers_missing() -> str | None:
    """Why the real-server tests cannot run here, or None when they can."""
    try:
        import gguf  # noqa: F401
        import llama_cpp.server  # noqa: F401
    except ImportError as exc:
        return (f"the servers extra is not installed ({exc.name} missing): "
                "pip install -e \".[dev,servers]\" to run the real llama.cpp server tests")
    return None


ANSWER_BYTE = ord("#")  # what the model says, over and over: never the end of its answer


def write_tiny_llama(path: Path, seed: int = 0) -> Path:
    """A random-weight llama GGUF (~0.1 MB): SentencePiece-style vocabulary of <unk>, <s>, </s>,
    the 256 byte tokens and a word separator, so any text tokenizes (one token per byte).

    One direction of every token's embedding is the same, and the output row of ``#`` reads it:
    whatever the prompt, the answer is ``#`` repeated until the answer limit (or the context) ends
    it. Random weights alone would stop at a random ``</s>``; this model never stops by itself, so
    a limit the server ignores shows in every answer, and greedy answers are the same in every run.
    """
    import gguf

    tokens: list[bytes] = [b"<unk>", b"<s>", b"</s>", *(f"<0x{b:02X}>".encode() for b in range(256)), "\u2581".encode()]
    types = [gguf.TokenType.UNKNOWN, gguf.TokenType.CONTROL, gguf.TokenType.CONTROL,
             *([gguf.TokenType.BYTE] * 256), gguf.TokenType.NORMAL]
    vocab = len(tokens)
    writer = gguf.GGUFWriter(str(path), "llama")
    writer.add_name("meceng-tiny-random")
    writer.add_context_length(TRAINED_CONTEXT)
    writer.add_embedding_length(EMBED)
    writer.add_block_count(LAYERS)
    writer.add_feed_forward_length(FFN)
    writer.add_head_count(HEADS)
    writer.add_head_count_kv(HEADS)
    writer.add_rope_dimension_count(EMBED // HEADS)
    writer.add_layer_norm_rms_eps(1e-5)
    writer.add_file_type(gguf.LlamaFileType.ALL_F32)
    writer.add_tokenizer_model("llama")
    writer.add_token_list(tokens)
    writer.add_token_scores([0.0] * vocab)
    writer.add_token_types(types)
    writer.add_unk_token_id(0)
    writer.add_bos_token_id(1)
    writer.add_eos_token_id(2)
    writer.add_add_bos_token(True)
    writer.add_chat_template(CHAT_TEMPLATE)
    rng = np.random.default_rng(seed)

    def weights(*shape: int) -> np.ndarray[Any, Any]:
        return (rng.standard_normal(shape) * 0.05).astype(np.float32)

    embedding = weights(vocab, EMBED)
    embedding[:, 0] = 1.0  # the shared direction
    output = weights(vocab, EMBED)
    output[3 + ANSWER_BYTE, 0] = 2.0  # token 3 + b is the byte b
    writer.add_tensor("token_embd.weight", embedding)
    writer.add_tensor("output_norm.weight", np.ones(EMBED, dtype=np.float32))
    writer.add_tensor("output.weight", output)
    for block in range(LAYERS):
        for name in ("attn_q", "attn_k", "attn_v", "attn_output"):
            writer.add_tensor(f"blk.{block}.{name}.weight", weights(EMBED, EMBED))
        writer.add_tensor(f"blk.{block}.attn_norm.weight", np.ones(EMBED, dtype=np.float32))
        writer.add_tensor(f"blk.{block}.ffn_norm.weight", np.ones(EMBED, dtype=np.float32))
        writer.add_tensor(f"blk.{block}.ffn_gate.weight", weights(FFN, EMBED))
        writer.add_tensor(f"blk.{block}.ffn_up.weight", weights(FFN, EMBED))
        writer.add_tensor(f"blk.{block}.ffn_down.weight", weights(EMBED, FFN))
    writer.write_header_to_file()
    writer.write_kv_data_to_file()
    writer.write_tensors_to_file()
    writer.close()
    return path


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


class LlamaServer:
    """``python -m llama_cpp.server`` in its own process (and session) on 127.0.0.1.

    ``start`` waits until ``/v1/models`` answers; ``kill`` ends it at once (SIGKILL, as a crash
    would); ``start`` again brings it back on the same port, as a user restarts a server.
    """

    def __init__(self, model: Path, n_ctx: int = 8192, port: int | None = None, log: Path | None = None) -> None:
        self.model, self.n_ctx = model, n_ctx
        self.port = port or free_port()
        self.log = log or model.with_suffix(".server.log")
        self.proc: subprocess.Popen[bytes] | None = None

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def start(self, timeout_s: float = 120.0) -> LlamaServer:
        args = [sys.executable, "-m", "llama_cpp.server", "--model", str(self.model), "--model_alias", SERVED_NAME,
                "--host", "127.0.0.1", "--port", str(self.port), "--n_ctx", str(self.n_ctx), "--n_threads", "1",
                "--n_batch", "512", "--flash_attn", "True", "--verbose", "False"]
        with open(self.log, "ab") as out:
            self.proc = subprocess.Popen(args, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                         start_new_session=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                raise RuntimeError(f"llama_cpp.server exited with {self.proc.returncode}: {self.log_tail()}")
            try:
                if httpx.get(f"{self.url}/models", timeout=2.0).status_code == 200:
                    return self
            except httpx.TransportError:
                pass
            time.sleep(0.2)
        self.kill()
        raise RuntimeError(f"llama_cpp.server did not answer within {timeout_s:.0f} s: {self.log_tail()}")

    def freeze(self, frozen: bool = True) -> None:
        """Stop (SIGSTOP) or continue the server: stopped, it still accepts connections (the kernel
        does) and answers nothing, as a hung server does."""
        assert self.proc is not None
        os.killpg(self.proc.pid, signal.SIGSTOP if frozen else signal.SIGCONT)

    def kill(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGKILL)
            self.proc.wait()
        self.proc = None

    def log_tail(self) -> str:
        return self.log.read_text(errors="replace")[-2000:] if self.log.exists() else ""

    def __enter__(self) -> LlamaServer:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.kill()
